"""The peak thrust against the thrust bearing's static axial rating, with its static
safety factor."""

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
    everywhere,
    least,
    load_input,
    most,
)
from app.core.phrase import Amount, Phrase


def rating_source(app: Application) -> str:
    """Whose rating the thrust bearing's is, in words."""
    if app.support_unit is None:
        return "as given"
    return f"support unit {app.support_unit}"


class SupportStatic(Check):
    name = "support_static"
    why_none = (
        "the peak thrust exceeds the thrust bearing's static rating: a larger support unit, "
        "or a lower load or acceleration"
    )
    label = "Thrust bearing (static)"
    description = (
        "The screw's thrust bearing (the fixed-side support unit) carries the peak thrust "
        "of the move both ways, the load plus the force that accelerates or brakes the "
        "moving mass: it must stay within the bearing's static axial rating divided by the "
        "static safety factor (THK: at least 2 without vibration or impact, 5 with)."
    )
    quantity = "force"
    capacity_given = "support_static"
    formula = "F = F_peak; F_allowed = C0a / fs"
    source = (
        "THK, bearing unit static safety factor fs = C0a / Fmax (LM Guide Actuator "
        "selection); the support unit's static axial rating (its maker's)"
    )

    def applies(self, app: Application) -> bool:
        return app.support_static_n is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.axis.peak_force_n, q.support.support_allowed_n)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_peak": q.axis.peak_force_n,
            "C0a": app.support_static_n,
            "fs": app.support_static_safety_factor,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "Peak thrust {f} on the thrust bearing " + verb + " its allowed {allowed}: static "
            "axial rating {c0a} ({source}) / static safety factor {fs}.",
            {
                "f": Amount(r.axis.peak_force_n, "force"),
                "allowed": Amount(r.support.support_allowed_n, "force"),
                "c0a": Amount(app.support_static_n or 0.0, "force"),
                "source": rating_source(app),
                "fs": Amount(app.support_static_safety_factor, "factor"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "A thrust bearing with a static axial rating of at least {c0a}, or a peak thrust "
            "of at most {cap} (a lower load, acceleration or moving mass)." + MARGIN_NOTE,
            {
                "c0a": least(r.axis.peak_force_n * app.support_static_safety_factor, "force"),
                "cap": most(r.support.support_allowed_n, "force"),
            },
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return load_input(app, r.support.support_allowed_n)

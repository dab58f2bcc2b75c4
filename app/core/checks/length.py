"""Screw length against the longest screw the family makes in this variant."""

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
    most,
    same,
)
from app.core.input_rules import least_inputs
from app.core.phrase import Amount, Phrase


class Length(Check):
    name = "length"
    why_none = "no screw in the catalog is made this long: consider a ball screw or a belt"
    why_none_ball = "no ball screw in the catalog is made this long: consider a belt or a rack"
    label = "Length"
    description = (
        "The screw length between the supports against the longest screw made in this "
        "variant, which holds the machined ends beyond the supports too."
    )
    quantity = "length"
    formula = "L = L_screw; L_max = L_variant"
    source = "the family's length limit per variant (catalog data)"
    sources = ("max_length",)
    capacity_sources = ("max_length",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(t.max_length_given, same(t, app.length_m), t.max_length_m)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"L_screw": app.length_m, "L_variant": t.max_length_m}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        template = (
            "{L} between the supports is within the maximum {cap}; the screw's machined "
            "ends beyond the supports count against it too."
            if passed
            else ("{L} exceeds the maximum length {cap}.")
        )
        return Phrase(
            template,
            {"L": Amount(app.length_m, "length"), "cap": Amount(s.max_length_m or 0.0, "length")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        longer = (
            ", or choose a variant made longer"
            if reach.max_length_m > (s.max_length_m or 0.0)
            else ""
        )
        cap = most(s.max_length_m or 0.0, "length")
        # a screw shorter than the stroke (and the nut, or the span to the thrust bearing)
        # is no screw the inputs accept: then the stroke must shorten with it
        shortest = least_inputs(app).get("length_m")
        if shortest is not None and cap.value < shortest:
            variant = "Choose a variant made longer, or shorten" if longer else "Shorten"
            return Phrase(
                variant + " the stroke: a screw of at most {cap} is shorter than the stroke "
                "needs ({need})." + MARGIN_NOTE,
                {"cap": cap, "need": Amount(shortest, "length")},
            )
        return Phrase(
            "Shorten the screw to at most {cap}" + longer + "." + MARGIN_NOTE, {"cap": cap}
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {"length_m": s.max_length_m or 0.0}

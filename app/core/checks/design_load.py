"""Axial force against the design load of the size (when the catalog gives one)."""

from app.core.checks import register
from app.core.checks.base import (
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    ScrewSpec,
    load_input,
    where_given,
)
from app.core.phrase import Amount, Phrase


@register
class DesignLoad(Check):
    name = "design_load"
    label = "Design load"
    description = "The axial force against the load the nut of this size is designed for."
    quantity = "force"
    formula = "F = F_axial; F_design = F_size"
    source = "catalog design load of the size (see its provenance)"
    sources = ("design_load",)
    order = 60

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(where_given(t.design_load_n), q.force_n, t.design_load_n)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"F_axial": q.force_n, "F_size": t.design_load_n}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "{f} " + verb + " the design load {cap}.",
            {"f": Amount(r.force_n, "force"), "cap": Amount(s.design_load_n or 0.0, "force")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float]) -> Phrase:
        return Phrase(
            "Reduce the load to at most {cap} or choose a larger size.",
            {"cap": Amount(s.design_load_n or 0.0, "force")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {"load_n": load_input(app, s.design_load_n or 0.0)}

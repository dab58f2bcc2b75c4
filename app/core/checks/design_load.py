"""Axial force against the design load of the size (when the catalog gives one)."""

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
    load_input,
    where_given,
)
from app.core.phrase import Amount, Phrase


class DesignLoad(Check):
    name = "design_load"
    label = "Design load"
    description = (
        "The peak thrust (running load plus the force that accelerates or brakes the "
        "moving mass, the larger) "
        "against the load the nut of this size is designed for."
    )
    quantity = "force"
    formula = "F = F_peak; F_design = F_size"
    source = "catalog design load of the size (see its provenance)"
    sources = ("design_load",)
    capacity_sources = ("design_load",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(where_given(t.design_load_n), q.peak_force_n, t.design_load_n)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"F_peak": q.peak_force_n, "F_size": t.design_load_n}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "Peak thrust {f} " + verb + " the design load {cap}.",
            {
                "f": Amount(r.peak_force_n, "force"),
                "cap": Amount(s.design_load_n or 0.0, "force"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        larger = " or choose a larger size" if reach.max_design_load_n >= r.peak_force_n else ""
        return Phrase(
            "Reduce the peak thrust to at most {cap}" + larger + ".",
            {"cap": Amount(s.design_load_n or 0.0, "force")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return load_input(app, s.design_load_n or 0.0)

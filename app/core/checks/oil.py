"""A variant that must not meet oil (e.g. a dry-film coating) where oil may be present."""

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
)
from app.core.phrase import Phrase


class OilCompatibility(Check):
    name = "coating_environment"
    why_none = "no nut suits this environment (oil, coating): choose another nut material"
    label = "Oil and lubricants"
    description = (
        "Some variants (a dry-film coating) must not be lubricated or run where oil may "
        "reach them (oil around the axis, or a greased or oiled nut); the family's data "
        "says which."
    )
    formula = "passes when oil_compatible or not (oil_present or lubricated)"
    source = "the family's rule per variant (catalog data)"
    sources = ("oil_compatible",)
    capacity_sources = ("oil_compatible",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        unsuited = ~t.oil_compatible
        return Measure(unsuited, flagged=unsuited & np.bool_(app.oil_reaches_nut))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "oil_compatible": t.oil_compatible,
            "oil_present": app.oil_present,
            "lubricated": app.lubricated,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if passed:
            return Phrase("No oil or grease reaches it: this variant may be used.")
        if app.lubricated:
            return Phrase(
                "This variant must not be lubricated, and the nut is {lubrication}.",
                {"lubrication": app.lubrication},
            )
        return Phrase("This variant must not be used where oil contamination is possible.")

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if app.lubricated and not app.oil_present:
            return Phrase("Run the nut dry, or use a variant rated for oil (uncoated).")
        return Phrase("Use a variant rated for oil (uncoated).")

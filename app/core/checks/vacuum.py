"""In a vacuum a nut must have published outgassing data: a lubricated nut's oil or grease
evaporates, and a polymer outgasses; without data its vacuum use is unproven."""

import numpy as np

from app.core.checks.base import (
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Mask,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
)
from app.core.phrase import Amount, Phrase


def outgassing_known(t: CandidateTable) -> Mask:
    """Whether each candidate's nut has published outgassing data."""
    return np.array([bool(s.outgassing) for s in t.screws], dtype=bool)


class Vacuum(Check):
    name = "vacuum"
    why_none = "no nut is rated for vacuum: consider a vacuum-rated ball screw"
    label = "Vacuum (outgassing)"
    kind = "advice"
    description = (
        "In a vacuum an oiled or greased nut loses its lubricant and a polymer nut "
        "outgasses: a nut is judged fit only where its outgassing has been measured (the "
        "seed's polyacetal nut: weight loss at 1e-4 torr over time) and it runs dry, as it "
        "was measured; others are warned, and no rating counts a lubricant there."
    )
    formula = "passes when (outgassing_known and not lubricated) or not vacuum"
    source = "seed catalog, degassing in a vacuum at 1e-4 torr (weight loss by hours)"
    sources = ("outgassing",)
    capacity_sources = ("outgassing",)

    def applies(self, app: Application) -> bool:
        return app.vacuum

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        unfit = ~outgassing_known(t) | np.bool_(app.lubricated)
        return Measure(np.ones(len(t), dtype=bool), flagged=unfit & np.bool_(app.vacuum))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "outgassing_known": outgassing_known(t),
            "lubricated": app.lubricated,
            "vacuum": app.vacuum,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if not passed and s.outgassing and app.lubricated:
            return Phrase(
                f"The nut is {app.lubrication}: in a vacuum its lubricant evaporates and "
                "outgasses (the nut's measured outgassing is its own, run dry), and its "
                "PV is judged without it."
            )
        if not passed:
            return Phrase(
                "No outgassing data for this nut (an oiled or greased nut loses its "
                "lubricant in a vacuum; a polymer outgasses): its vacuum use is unproven."
            )
        hours, percent = s.outgassing[-1]
        return Phrase(
            "Measured outgassing: {w} % weight loss after {h} h at 1e-4 torr.",
            {"w": Amount(percent, "factor"), "h": Amount(hours, "factor")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if s.outgassing and app.lubricated:
            return Phrase("Run the nut dry, as its outgassing was measured.")
        return Phrase(
            "Use a nut whose outgassing is measured, such as the seed's polyacetal, run dry."
        )

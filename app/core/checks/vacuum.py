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
        "seed's polyacetal nut: weight loss at 1e-4 torr over time); others are warned."
    )
    formula = "passes when outgassing_known or not vacuum"
    source = "seed catalog, degassing in a vacuum at 1e-4 torr (weight loss by hours)"
    sources = ("outgassing",)
    capacity_sources = ("outgassing",)

    def applies(self, app: Application) -> bool:
        return app.vacuum

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        known = outgassing_known(t)
        return Measure(np.ones(len(t), dtype=bool), flagged=~known & np.bool_(app.vacuum))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"outgassing_known": outgassing_known(t), "vacuum": app.vacuum}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if not passed:
            return Phrase(
                "No outgassing data for this nut (an oiled or greased nut loses its "
                "lubricant in a vacuum; a polymer outgasses): its vacuum use is unproven."
            )
        hours, percent = s.outgassing[-1]
        return Phrase(
            "Measured outgassing: {w} % weight loss after {h} at 1e-4 torr.",
            {"w": Amount(percent, "factor"), "h": Amount(hours * 3600.0, "time")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase("Use a nut whose outgassing is measured, such as the seed's polyacetal.")

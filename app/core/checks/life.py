"""Rated life, in years of the user's duty, against the life required."""

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
    same,
)
from app.core.phrase import Amount, Phrase


class Life(Check):
    name = "life"
    label = "Life"
    description = (
        "The rated travel of the nut (low end of its range) in years of the given stroke "
        "and cycles per day, against the life required; a nut rated by its wear rate "
        "instead is judged by the nut wear life."
    )
    quantity = "years"
    formula = "life_required = Y_req; life = travel_min / (2 * stroke * cycles * 365)"
    source = "seed catalog, Anti-Backlash Life (rated travel)"
    sources = ("life",)
    capacity_sources = ("life",)

    def applies(self, app: Application) -> bool:
        # without a duty there is nothing to turn the rated travel into years
        return bool(app.required_life_years is not None and app.stroke_m and app.cycles_per_day)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        unrated = np.isnan(q.life_years_min)
        worn = ~np.isnan(t.wear_rate_m2_n)  # the wear-life check judges these
        required = same(t, app.required_life_years)
        return Measure(~(unrated & worn), required, q.life_years_min, flagged=unrated & ~worn)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "Y_req": app.required_life_years,
            "travel_min": t.life_min_m,
            "stroke": app.stroke_m,
            "cycles": app.cycles_per_day,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if np.isnan(r.life_years_min):
            return Phrase("No life rating is published for this series.")
        verb = "At least {years} rated" if passed else "Only {years} rated (low end)"
        return Phrase(
            verb + ", {required} required.",
            {
                "years": Amount(r.life_years_min, "years"),
                "required": Amount(app.required_life_years or 0.0, "years"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if np.isnan(r.life_years_min):
            return Phrase("Choose a series whose life is rated.")
        return Phrase(
            "Choose a variant or series with a longer rated life, or shorten the stroke or "
            "the duty."
        )

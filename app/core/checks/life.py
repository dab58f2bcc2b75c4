"""Rated life, in years of the user's duty, against the life required."""

import numpy as np

from app.core import motion
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
        "and cycles (or hours) per day, against the life required. The seed gives no load "
        "for its rating and says life varies with load, so where the nut material has a "
        "wear rate the rated travel counts for no more than the nut's wear life at the "
        "cycle's wear thrust (Archard's law, the same as the nut wear life's); a nut rated "
        "by its wear rate alone is judged by the nut wear life."
    )
    quantity = "years"
    formula = (
        "life_required = Y_req; life = min(travel_min, wear_travel) / (2 * stroke * cycles * 365)"
    )
    source = (
        "seed catalog, Anti-Backlash Life (rated travel; 'life will vary with loading, "
        "operating environment and duty cycle'); Archard's law for the load"
    )
    sources = ("life", "wear_rate", "allowed_wear")
    capacity_sources = ("life", "wear_rate", "allowed_wear")

    def applies(self, app: Application) -> bool:
        # without a duty there is nothing to turn the travel into years
        return motion.life_judged(app)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        unrated = np.isnan(q.life.life_years_min)
        worn = ~np.isnan(t.wear_rate_m2_n)  # the wear-life check judges these
        required = same(t, app.required_life_years)
        # a ball nut has no rated travel: its L10 life is the ball-life check
        judged = ~(unrated & worn) & ~t.ball
        return Measure(judged, required, q.life.life_years_min, flagged=unrated & ~worn & ~t.ball)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "Y_req": app.required_life_years,
            "travel_min": t.life_min_m,
            "wear_travel": np.where(np.isnan(q.life.wear_travel_m), np.inf, q.life.wear_travel_m),
            "stroke": motion.equivalent_stroke(app),
            "cycles": motion.cycles_per_day(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if np.isnan(r.life.life_years_min) and _run_dry(app, s):
            return Phrase(
                "The nut's wear rate is a lubricated nut's, and it runs dry: its wear run "
                "dry is not rated."
            )
        if np.isnan(r.life.life_years_min):
            return Phrase("No life rating or nut wear rate is given for this screw's nut.")
        values = {
            "years": Amount(r.life.life_years_min, "years"),
            "required": Amount(app.required_life_years or 0.0, "years"),
            "seed": Amount(s.life_min_m or 0.0, "travel"),
            "travel": Amount(r.life.life_travel_min_m, "travel"),
            "thrust": Amount(r.life.wear_force_n, "force"),
        }
        if r.life.life_travel_min_m < (s.life_min_m or 0.0):
            # the wear at the rate's central value: its range moves it (the life band)
            return Phrase(
                ("{years}" if passed else "Only {years}")
                + ", {required} required: the seed's {seed} of travel, cut to {travel} by "
                "the nut's wear at the cycle's wear thrust of {thrust} (Archard's law at "
                "the assumed wear rate's central value, whose range the life band spans; "
                "the seed gives no load for its rating).",
                values,
            )
        verb = "At least {years} rated" if passed else "Only {years} rated (low end)"
        return Phrase(verb + ", {required} required (the seed's {seed} of travel).", values)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if np.isnan(r.life.life_years_min) and _run_dry(app, s):
            return Phrase("Grease or oil the nut (the nut lubrication input), whose wear is rated.")
        if np.isnan(r.life.life_years_min) and reach.families is None:  # a screw of one's own
            return Phrase(
                "Give the nut a material whose wear is rated (a catalog nut material, with "
                "the thread pitch), or leave the required life out."
            )
        if np.isnan(r.life.life_years_min):
            return Phrase("Choose a series whose life is rated.")
        return Phrase(
            "Choose a variant or series with a longer rated life, or shorten the stroke or "
            "the duty; where the nut's wear cuts the rating, a lighter load or a gentler "
            "acceleration."
        )


def _run_dry(app: Application, s: ScrewSpec) -> bool:
    """Whether ``s`` is a nut rated lubricated that the axis runs dry (``dry_run``: none
    given, or oil or grease in a vacuum)."""
    return s.lubricated_rating and app.lubrication_counted == "dry"

"""Wear life of a sliding nut (Archard's law), in years of the user's duty, against the
life required; shown as a band over the published scatter of the wear rate."""

import numpy as np

from app.core import load_caps, motion
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
from app.core.phrase import Amount, Phrase, figures

#: The catalog's name of the ranged wear rate (its ends give the life band).
WEAR_RATE = "specific_wear_rate_mm3_n_m"
#: The screw's values (``ScrewSpec`` fields) only the nut's wear life reads, which caps
#: the rated life too: moving them changes no verdict where no life is judged
#: (``motion.life_judged``), so robustness then leaves such variants unscreened.
WEAR_ONLY = frozenset({"wear_rate_m2_n", "allowed_wear_fraction"})


def life_band(s: ScrewSpec) -> tuple[float, float]:
    """The life at the high and at the low end of the wear rate's range, as shares of the
    nominal life (inversely proportional to the rate); (1, 1) without a range."""
    ends = s.assumption_ends.get(WEAR_RATE)
    nominal = s.wear_rate_m2_n
    if ends is None or nominal is None:
        return 1.0, 1.0
    low_rate, high_rate = (end["wear_rate_m2_n"] for end in ends)
    return nominal / high_rate, nominal / low_rate


class WearLife(Check):
    name = "wear_life"
    why_none = "no nut lasts this duty: consider a ball screw"
    label = "Nut wear life"
    description = (
        "Archard's law: the thrust over the nut's loaded flanks wears them by the nut "
        "material's specific wear rate per metre slid. The thrust is the cycle's wear "
        "thrust: the nut's thrust in every segment of both moves (the load with its "
        "direction, the weight on a vertical axis, m a while accelerating and braking), "
        "weighted by the segment's travel. The nut travel until the wear reaches the "
        "allowed fraction of the flank height (an ISO nut's thread a quarter of the pitch "
        "thinner, the end of a nut's full life), in years of the given stroke and cycles "
        "(or hours) per day, against the life required; a nut with a seed life rating is "
        "judged by the life check, which this wear life caps. Wear rates and life tests "
        "scatter 2-3:1, so the life is shown as a band."
    )
    quantity = "years"
    formula = "Y = Y_req; Y_wear = f_w * H / (k * p) / (helix / lead) / (2 * stroke * cycles * 365)"
    source = (
        "Archard's law h = k p s, summed over the cycle's segments (the load-spectrum "
        "mean, Steinmeyer, duty cycle and equivalent load, with the wear law's exponent 1); "
        "Neale, Tribology Handbook A5 (wear depth rate K P V); "
        "wear rates by nut material (catalog); allowed wear: Helix Linear, a quarter of "
        "the pitch off the thread; scatter: Roton, life tests vary 2-3:1"
    )
    sources = ("wear_rate", "allowed_wear", "nut_length", "pitch")
    capacity_sources = ("wear_rate", "allowed_wear", "nut_length")

    def applies(self, app: Application) -> bool:
        return motion.life_judged(app)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        required = same(t, app.required_life_years)
        unrated = np.isnan(t.life_min_m)  # the life check judges a rated nut's wear
        return Measure(
            where_given(q.life.wear_life_years) & unrated, required, q.life.wear_life_years
        )

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        flanks = ~np.isnan(q.nut.flank_area_m2)
        return {
            "Y_req": app.required_life_years,
            "f_w": t.allowed_wear_fraction,
            "H": np.where(flanks, t.flank_height_m, t.thread_depth_m),
            "k": t.wear_rate_m2_n,
            "p": q.life.wear_force_n / np.where(flanks, q.nut.flank_area_m2, q.nut.contact_area_m2),
            "helix": np.where(flanks, t.flank_helix_travel_m, t.helix_travel_m),
            "lead": t.lead_m,
            "stroke": motion.equivalent_stroke(app),
            "cycles": motion.cycles_per_day(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        low_m, high_m = (r.life.wear_travel_m * share for share in life_band(s))
        cycle_m = 2.0 * (motion.equivalent_stroke(app) or 0.0)
        verb = "meets" if passed else "falls short of"
        return Phrase(
            "Nut wear life {travel} of travel at the cycle's wear thrust of {thrust} ({low} "
            "to {high} over the wear rate's scatter), {cycles} cycles: {years}, which "
            + verb
            + " the {required} required.",
            {
                "travel": Amount(r.life.wear_travel_m, "travel"),
                "thrust": Amount(r.life.wear_force_n, "force"),
                "low": Amount(low_m, "travel"),
                "high": Amount(high_m, "travel"),
                "cycles": figures(r.life.wear_travel_m / cycle_m, digits_below=15),
                "years": Amount(r.life.wear_life_years, "years"),
                "required": Amount(app.required_life_years or 0.0, "years"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "Wear falls with the flank pressure and the sliding per metre: a longer nut, a "
            "larger size, a longer lead or a nut material that wears less (bronze, oiled); "
            "or a lighter load or moving mass, a gentler acceleration, a shorter stroke or "
            "fewer cycles."
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float] | None:
        # the life is inversely proportional to the cycle's wear thrust
        years = app.required_life_years
        if not years or not np.isfinite(r.life.wear_life_years):
            return None
        load_n = load_caps.largest_load_for_wear(
            app, r.life.wear_force_n * r.life.wear_life_years / years
        )
        return None if load_n is None else {"load_n": load_n}

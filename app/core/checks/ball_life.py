"""Ball screw: the nut's L10 rated fatigue life, in years of the user's duty, against the
life required (ISO 3408-5)."""

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
from app.core.duty import operating_mean_load, travel_thrusts
from app.core.formulas import ballscrew, life
from app.core.phrase import Amount, Phrase


def mean_load(app: Application) -> float:
    """The cycle's cubic mean axial load [N], each moving segment weighted by its travel
    (its revolutions); 0 without a stroke."""
    return float(ballscrew.cubic_mean_load(*travel_thrusts(app)))


def life_years(
    app: Application,
    dynamic_load_n: Array,
    lead_m: Array,
    preload_n: Array,
    thrusts: tuple[list[float], list[float]] | None = None,
) -> Array:
    """The L10 life in years of the duty [year] for each nut of rating Ca [N], lead [m]
    and preload [N], at its operating mean load (``operating_mean_load``); ``thrusts``
    as there."""
    thrusts = thrusts or travel_thrusts(app)
    cycles = motion.cycles_per_day(app) or 0.0
    mean_n = operating_mean_load(app, preload_n, thrusts)
    revolutions = ballscrew.rated_life_revolutions(dynamic_load_n, app.ball_load_factor, mean_n)
    revolutions_per_day = sum(thrusts[1]) / lead_m * cycles
    return np.asarray(revolutions / (revolutions_per_day * life.DAYS_PER_YEAR), dtype=np.float64)


class BallLife(Check):
    name = "ball_life"
    why_none = (
        "no ball nut in the catalog is rated for this life under this load: a larger ball "
        "screw, a planetary roller screw, or a lighter duty"
    )
    label = "L10 life (ball screw)"
    description = (
        "A ball nut's rated fatigue life L10 = (Ca / (f_w F_m))^3 x 10^6 revolutions "
        "(ISO 3408-5), with F_m the cycle's cubic mean of the load the ball track carries "
        "(each moving segment's thrust weighted by its revolutions; in a preloaded nut "
        "raised by the preload F_pr below 2^(3/2) F_pr, HIWIN F 3.7) and the load factor "
        "f_w (1.2 by default, the top of HIWIN's 1.1 to 1.2 without impact; 1.3 to 1.8 in "
        "normal operation), in years of the given stroke and cycles (or hours) per "
        "day, against the life required. Applies to ball screws only."
    )
    quantity = "years"
    formula = (
        "life_required = Y_req; life = (Ca / (f_w * F_m))**3 * 1e6 / (travel / lead * cycles * 365)"
    )
    source = (
        "ISO 3408-5 rated life; HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, "
        "sec. 3.7.2 F 3.7 to F 3.10 (preload, cubic mean load, operating factor)"
    )
    sources = ("dynamic_load", "preload")
    capacity_sources = ("dynamic_load", "preload")

    def applies(self, app: Application) -> bool:
        # the cheap conditions first: the mean load works out the whole cycle
        return bool(
            app.required_life_years is not None
            and app.stroke_m
            and motion.cycles_per_day(app)
            and mean_load(app) > 0.0
        )

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        with np.errstate(invalid="ignore", divide="ignore"):
            years = life_years(app, t.dynamic_load_n, t.lead_m, t.preload_n)
        return Measure(t.ball.copy(), same(t, app.required_life_years), years)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        thrusts = travel_thrusts(app)
        return {
            "Y_req": app.required_life_years,
            "Ca": t.dynamic_load_n,
            "f_w": app.ball_load_factor,
            "F_m": operating_mean_load(app, t.preload_n, thrusts),
            "travel": sum(thrusts[1]),
            "lead": t.lead_m,
            "cycles": motion.cycles_per_day(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        ca, preload = s.dynamic_load_n or 0.0, np.array([s.preload_n or 0.0])
        thrusts = travel_thrusts(app)
        years = life_years(app, np.array([ca]), np.array([s.lead_m]), preload, thrusts)
        verb = "{years} rated (L10)" if passed else "Only {years} rated (L10)"
        values = {
            "years": Amount(float(years[0]), "years"),
            "required": Amount(app.required_life_years or 0.0, "years"),
            "ca": Amount(ca, "force"),
            "fm": Amount(float(operating_mean_load(app, preload, thrusts)[0]), "force"),
            "fw": Amount(app.ball_load_factor, "factor"),
        }
        text = (
            verb + ", {required} required: Ca = {ca} against the cycle's cubic mean load "
            "{fm} times the load factor {fw}."
        )
        if s.preload_n:
            values["preload"] = Amount(s.preload_n, "force")
            values["axis"] = Amount(float(ballscrew.cubic_mean_load(*thrusts)), "force")
            text += (
                " The mean counts the nut's preload {preload} (the axis's thrust alone: {axis})."
            )
        return Phrase(text, values)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "Choose a ball nut with a higher dynamic load rating Ca (a larger size, more "
            "ball circuits), or lighten the load, the acceleration or the duty."
        )

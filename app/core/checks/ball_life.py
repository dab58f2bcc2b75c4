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
from app.core.duty import (
    ball_life_revolutions,
    ball_load_factors,
    operating_mean_load,
    side_mean_loads,
    travel_thrusts,
)
from app.core.formulas import ballscrew, life
from app.core.phrase import Amount, Phrase

#: What the life's sentence adds where a short stroke raised the load factor.
SHORT_NOTE = (
    " (raised for a stroke under 3 nut lengths: HIWIN's operating condition 3.0 to 5.0, F 3.8)"
)


def life_years(
    app: Application,
    dynamic_load_n: Array,
    lead_m: Array,
    preload_n: Array,
    nut_length_m: Array,
    thrusts: tuple[list[float], list[float]] | None = None,
) -> Array:
    """The L10 life in years of the duty [year] for each nut of rating Ca [N], lead [m],
    preload [N] and length [m] (``duty.ball_life_revolutions``: both sides of a preloaded
    nut, its load factor raised on a short stroke); ``thrusts`` as there."""
    thrusts = thrusts or travel_thrusts(app)
    cycles = motion.cycles_per_day(app) or 0.0
    factor = ball_load_factors(app, nut_length_m)
    revolutions = ball_life_revolutions(app, dynamic_load_n, preload_n, factor, thrusts)
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
        "A ball nut's rated fatigue life L10 (ISO 3408-5) in years of the given stroke and "
        "cycles (or hours) per day, against the life required, with the load factor f_w "
        "(1.2 by default, the top of HIWIN's 1.1 to 1.2 without impact; 1.3 to 1.8 in "
        "normal operation; at least 3.0 where the stroke is under 3 nut lengths, the "
        "bottom of HIWIN's 3.0 to 5.0 for a short stroke, F 3.8). A nut with play: "
        "L10 = (Ca / (f_w F_m))^3 x 10^6 revolutions, "
        "F_m the cycle's cubic mean thrust, each moving segment weighted by its "
        "revolutions. A preloaded nut rolls on both sides: in each segment the side the "
        "thrust presses carries F_b = (1 + F / 2^(3/2) F_pr)^(3/2) F_pr and the other "
        "F_b - F (0 from the disengagement force 2^(3/2) F_pr on; HIWIN F 3.7), each "
        "side's cubic mean F_bm1, F_bm2 gives a life L1, L2, and the nut lives "
        "L = (L1^(-10/9) + L2^(-10/9))^(-9/10) (HIWIN sec. 3.7.2 d)), or the one-sided "
        "(Ca / (f_w F_m))^3 x 10^6 with every segment at F_b where that is shorter. "
        "Applies to ball screws only."
    )
    quantity = "years"
    formula = (
        "life_required = Y_req; life = (min(((f_w * F_bm1 / Ca)^(10/3) + (f_w * F_bm2 / Ca)"
        "^(10/3))^(-9/10), (Ca / (f_w * F_m))^3) if F_pr > 0 else (Ca / (f_w * F_m))^3) "
        "* 1e6 / (travel / lead * cycles * 365)"
    )
    source = (
        "ISO 3408-5 rated life; HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, "
        "sec. 3.7.2 F 3.6 to F 3.10 (preload, cubic mean load, operating factor) and "
        "d) 'Axial loading on both sides' with its flow chart for calculating service "
        "life (L1, L2 and L = (L1^(-10/9) + L2^(-10/9))^(-9/10))"
    )
    sources = ("dynamic_load", "preload")
    capacity_sources = ("dynamic_load", "preload")

    def applies(self, app: Application) -> bool:
        """A life is required of a duty over a stroke. Whatever the thrust: a preloaded
        nut's balls carry its preload with no thrust at all (a nut with play then lives
        forever, and passes)."""
        return bool(
            app.required_life_years is not None and app.stroke_m and motion.cycles_per_day(app)
        )

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        with np.errstate(invalid="ignore", divide="ignore"):
            years = life_years(app, t.dynamic_load_n, t.lead_m, t.preload_n, t.nut_length_m)
        return Measure(t.ball.copy(), same(t, app.required_life_years), years)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        thrusts = travel_thrusts(app)
        side1, side2 = side_mean_loads(app, t.preload_n, thrusts)
        return {
            "Y_req": app.required_life_years,
            "Ca": t.dynamic_load_n,
            "f_w": ball_load_factors(app, t.nut_length_m),
            "F_m": operating_mean_load(app, t.preload_n, thrusts),
            "F_bm1": side1,
            "F_bm2": side2,
            "F_pr": t.preload_n,
            "travel": sum(thrusts[1]),
            "lead": t.lead_m,
            "cycles": motion.cycles_per_day(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        ca, preload = s.dynamic_load_n or 0.0, np.array([s.preload_n or 0.0])
        nut = np.array([np.nan if s.nut_length_m is None else s.nut_length_m])
        thrusts = travel_thrusts(app)
        years = life_years(app, np.array([ca]), np.array([s.lead_m]), preload, nut, thrusts)
        factor = float(ball_load_factors(app, nut)[0])
        verb = "{years} rated (L10)" if passed else "Only {years} rated (L10)"
        values = {
            "years": Amount(float(years[0]), "years"),
            "required": Amount(app.required_life_years or 0.0, "years"),
            "ca": Amount(ca, "force"),
            "fm": Amount(float(operating_mean_load(app, preload, thrusts)[0]), "force"),
            "fw": Amount(factor, "factor"),
        }
        short = SHORT_NOTE if factor > app.ball_load_factor else ""
        if not np.isfinite(years[0]):
            return Phrase(
                "No thrust loads the balls over the cycle and the nut has no preload: no "
                "fatigue, whatever the life required ({required}).",
                values,
            )
        if not (s.preload_n and s.preload_n > 0.0):
            text = (
                verb + ", {required} required: Ca = {ca} against the cycle's cubic mean load "
                "{fm} times the load factor {fw}" + short + "."
            )
            return Phrase(text, values)
        return _preloaded(app, verb, values, preload, thrusts, short)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "Choose a ball nut with a higher dynamic load rating Ca (a larger size, more "
            "ball circuits), or lighten the load, the acceleration or the duty."
        )


def _preloaded(
    app: Application,
    verb: str,
    values: dict[str, Amount],
    preload: Array,
    thrusts: tuple[list[float], list[float]],
    short: str,
) -> Phrase:
    """``BallLife.explain`` for a preloaded nut: its two sides' mean loads and lives
    combined, or the one-sided mean where that rates shorter
    (``ballscrew.nut_life_revolutions``), at its load factor ``values["fw"]`` (``short``:
    the words where a short stroke raised it)."""
    side1, side2 = side_mean_loads(app, preload, thrusts)
    ca, factor = values["ca"].value, values["fw"].value
    both = ballscrew.two_sided_life_revolutions(ca, factor, side1[0], side2[0])
    one = ballscrew.rated_life_revolutions(ca, factor, values["fm"].value)
    values |= {
        "preload": Amount(float(preload[0]), "force"),
        "axis": Amount(float(ballscrew.cubic_mean_load(*thrusts)), "force"),
        "side1": Amount(float(side1[0]), "force"),
        "side2": Amount(float(side2[0]), "force"),
    }
    text = (
        verb + ", {required} required: Ca = {ca}, load factor {fw}" + short + ". The nut's "
        "preload {preload} loads both its sides (the axis's thrust alone: {axis}): cubic "
        "mean loads {side1} and {side2}, their lives combined as "
        "(L1^(-10/9) + L2^(-10/9))^(-9/10)."
    )
    if one < both:
        text += " One side under the cycle's mean load {fm} rates shorter, and is taken."
    return Phrase(text, values)

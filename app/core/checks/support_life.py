"""The thrust bearing's rating life (ISO 281) in years of the duty, against the life
required."""

from app.core import motion
from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    least,
    same,
    where_given,
)
from app.core.checks.support_static import rating_source
from app.core.phrase import Amount, Phrase


class SupportLife(Check):
    name = "support_life"
    why_none = (
        "the thrust bearing does not last this duty on any lead: a support unit of a higher "
        "dynamic rating"
    )
    label = "Thrust bearing life"
    description = (
        "The thrust bearing's basic rating life L10 = (Ca / (f_w Fm))^3 million "
        "revolutions (ISO 281, ball bearings), Fm the cube mean of the thrust over the "
        "travel of the cycle (every segment of both moves, weighted by its distance), f_w "
        "the load factor for vibration and shocks (the ball nut's, the same axis's), "
        "turned into years of the stroke and cycles per day through the lead, against the "
        "life required."
    )
    quantity = "years"
    capacity_given = "support_dynamic"
    formula = (
        "life_required = Y_req; "
        "life = (C_a / (f_w * F_m))^3 * 1e6 * lead / (2 * stroke * cycles * 365)"
    )
    source = (
        "ISO 281:2007 basic rating life (ball bearings); THK Ball Screw, average axial load; "
        "IKO, Needle Roller Bearings catalog, eq. (10) and Table 6 (bearing load = load "
        "factor x calculated load)"
    )

    def applies(self, app: Application) -> bool:
        # a duty of cycles or of hours a day (``motion.has_duty``), as the nut's lives
        duty = motion.has_duty(app) and app.required_life_years is not None
        return duty and app.support_dynamic_n is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        life = q.support.support_life_years
        return Measure(where_given(life), same(t, app.required_life_years), life)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "Y_req": app.required_life_years,
            "C_a": app.support_dynamic_n,
            "F_m": q.support.support_mean_load_n,
            "f_w": app.ball_load_factor,
            "lead": t.lead_m,
            "stroke": motion.equivalent_stroke(app),
            "cycles": motion.cycles_per_day(app),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "meets" if passed else "is short of"
        return Phrase(
            "The thrust bearing's L10 life {years} " + verb + " the {required} required: "
            "dynamic axial rating {ca} ({source}) under the cycle's cube-mean thrust {fm} "
            "times the load factor {fw}.",
            {
                "years": Amount(r.support.support_life_years, "years"),
                "required": Amount(app.required_life_years or 0.0, "years"),
                "ca": Amount(app.support_dynamic_n or 0.0, "force"),
                "source": rating_source(app),
                "fm": Amount(r.support.support_mean_load_n, "force"),
                "fw": Amount(app.ball_load_factor, "factor"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        # L10 grows as Ca^3: the rating that gives the required life
        ratio = (app.required_life_years or 0.0) / r.support.support_life_years
        needed = (app.support_dynamic_n or 0.0) * ratio ** (1.0 / 3.0)
        return Phrase(
            "A thrust bearing with a dynamic axial rating of at least {ca}, a longer lead "
            "(fewer turns for the travel), or a lower load or duty." + MARGIN_NOTE,
            {"ca": least(needed, "force")},
        )

"""Linear speed against the family's recommended speed for the lead (a band table)."""

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
    most,
    run_at_most,
    same,
)
from app.core.formulas.limits import band_speed_m_s
from app.core.phrase import Amount, Phrase


class TraverseSpeed(Check):
    name = "traverse_speed"
    slower_may_clear = True
    label = "Traverse speed"
    description = (
        "The family's table of the highest linear speed recommended for each lead band "
        "for optimum nut life (only for families that publish one). Advice: a faster "
        "screw is reported with a warning, not rejected, unless you ask for that."
    )
    kind = "advice"
    quantity = "speed"
    formula = "v = v_linear; v_allowed = v_band(lead)"
    source = "the family's traverse-speed table (catalog data)"
    sources = ("lead", "traverse_speed")
    capacity_sources = ("traverse_speed",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        limit = t.traverse_limit_m_s
        return Measure(t.traverse_limit_given, same(t, motion.reached_speed(app)), limit)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "v_linear": motion.reached_speed(app),
            "v_band": lambda lead: band_speed_m_s(lead, t.screws[0].traverse_bands),
            "lead": t.lead_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        limit = _limit(s)
        verb = "is within" if passed else "exceeds"
        note = ""
        values: dict[str, Amount | str] = {
            "v": Amount(motion.reached_speed(app), "speed"),
            "limit": Amount(limit, "speed"),
        }
        if not s.traverse_bands[0][0] <= s.lead_m <= s.traverse_bands[-1][1]:
            note = " (lead outside the table's {low} to {high}: nearest band)"
            values["low"] = Amount(s.traverse_bands[0][0], "length")
            values["high"] = Amount(s.traverse_bands[-1][1], "length")
        return Phrase("{v} " + verb + " the recommended {limit} for this lead" + note + ".", values)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        reached_m_s = motion.reached_speed(app)
        faster = [band for band in s.traverse_bands if band[2] >= reached_m_s]
        lead = reach.made_lead(s, faster[0][0], larger=True) if faster else None
        if lead is None:
            return Phrase(
                run_at_most(app) + " {limit}." + MARGIN_NOTE,
                {"limit": most(_limit(s), "speed")},
            )
        return Phrase(
            run_at_most(app) + " {limit}, or a lead of at least {lead}." + MARGIN_NOTE,
            {"limit": most(_limit(s), "speed"), "lead": Amount(lead, "length")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {"speed_m_s": _limit(s)}


def _limit(s: ScrewSpec) -> float:
    """The screw's band limit [m/s]."""
    return band_speed_m_s(s.lead_m, s.traverse_bands)

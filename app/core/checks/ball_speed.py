"""Ball screw: the peak screw speed against the maker's DN limit (the diameter [mm] times
speed [rpm], HIWIN sec. 3.7.6: the nominal, ball-centre diameter where it is above the
shaft's outer diameter, ``ballscrew.dn_diameter``), which bounds the ball recirculation's
noise, heat and life."""

import math

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
    at_most,
    most,
)
from app.core.formulas import ballscrew
from app.core.phrase import Amount, Phrase


class BallSpeed(Check):
    name = "ball_speed"
    slower_may_clear = True
    why_none = (
        "the speed exceeds every ball screw's DN limit: a belt drive, a rack and pinion or "
        "a linear motor"
    )
    label = "DN speed limit (ball screw)"
    description = (
        "A ball screw's peak speed against the maker's DN limit: the diameter [mm] times "
        "speed [rpm] at most 70,000 for rolled and 90,000 for ground ball screws (HIWIN sec. "
        "3.7.6), the diameter the nominal (ball-centre) one d_0, as Roton and THK take it, "
        "where it is above the shaft's outer diameter d_s HIWIN tables (less speed), "
        "beyond which the ball recirculation runs noisy and hot and its life drops. The "
        "critical speed of the shaft is checked separately. Applies to ball screws only."
    )
    quantity = "rpm"
    formula = "n = n_peak; n_DN = DN_max / (max(d_s, d_0) * 1000)"
    source = "HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, sec. 3.7.6 (DN value)"
    sources = ("dn_limit", "outer_diameter", "pitch_diameter")
    capacity_sources = ("dn_limit",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        limit = t.dn_speed_limit_rpm  # ballscrew.dn_speed_limit, worked out with the table
        return Measure(t.ball.copy(), q.motor.peak_rpm, limit)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "n_peak": q.motor.peak_rpm,
            "DN_max": t.dn_limit_mm_rpm,
            "d_s": t.outer_diameter_m,
            "d_0": t.pitch_diameter_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        limit = _limit_rpm(s)
        verb = "within" if passed else "above"
        return Phrase(
            "Peak speed {n}, " + verb + " the {limit} that the maker's DN limit of {dn} "
            "mm rpm allows this diameter.",
            {
                "n": Amount(r.motor.peak_rpm, "rpm"),
                "limit": Amount(limit, "rpm"),
                "dn": Amount(s.dn_limit_mm_rpm or 0.0, "factor"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        limit = _limit_rpm(s)
        return Phrase(
            "Keep the screw at or below {n}: a longer lead for the same linear speed, a "
            "ground screw (higher DN limit) or a lower speed." + MARGIN_NOTE,
            {"n": most(limit, "rpm")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        limit = _limit_rpm(s)
        return {"speed_m_s": at_most(limit) / 60.0 * s.lead_m}


def _limit_rpm(s: ScrewSpec) -> float:
    """The speed ``s``'s DN limit allows [rpm] (``ballscrew.dn_speed_limit`` on
    ``ballscrew.dn_diameter``)."""
    d_0 = math.nan if s.pitch_circle_diameter_m is None else s.pitch_circle_diameter_m
    diameter = float(ballscrew.dn_diameter(s.outer_diameter_m, d_0))
    return ballscrew.dn_speed_limit(s.dn_limit_mm_rpm or 0.0, diameter)

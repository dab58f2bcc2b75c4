"""Flank sliding speed of a polymer nut against the material's maximum sliding speed."""

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
    where_given,
)
from app.core.phrase import Amount, Phrase


class MaxSlidingSpeed(Check):
    name = "max_sliding_speed"
    slower_may_clear = True
    why_none = "no nut slides this fast: consider a longer lead, a ball screw or a belt"
    label = "Nut sliding speed"
    description = (
        "The speed at which the nut's flanks slide on the screw (the helix at the pitch "
        "diameter d2, n times per second) against the nut material's maximum."
    )
    quantity = "speed"
    formula = "v = n / 60 * sqrt(lead^2 + (pi * d_2)^2); v_max = v_nut"
    source = "the nut material's maximum sliding speed (catalog, see its provenance)"
    sources = ("max_sliding_speed", "pitch")
    capacity_sources = ("max_sliding_speed",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        capacity = t.max_sliding_speed_m_s
        speed = q.nut.sliding_speed_m_s
        return Measure(t.max_sliding_speed_given & where_given(speed), speed, capacity)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "n": q.axis.rpm,
            "lead": t.lead_m,
            "d_2": t.flank_pitch_diameter_m,
            "v_nut": t.max_sliding_speed_m_s,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "The flank sliding speed {v} " + verb + " the nut material's maximum {cap}.",
            {
                "v": Amount(r.nut.sliding_speed_m_s, "speed"),
                "cap": Amount(s.max_sliding_speed_m_s or 0.0, "speed"),
            },
        )

    def _max_linear_speed(self, app: Application, s: ScrewSpec, r: Quantities[float]) -> float:
        """The linear speed at which the sliding speed meets the maximum (proportional to
        the speed reached, the triangle's peak on a short stroke)."""
        speed = motion.reached_speed(app)
        return speed * (s.max_sliding_speed_m_s or 0.0) / r.nut.sliding_speed_m_s

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            run_at_most(app) + " {speed}, or choose a larger lead (fewer turns for the same "
            "travel)." + MARGIN_NOTE,
            {"speed": most(self._max_linear_speed(app, s, r), "speed")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {"speed_m_s": self._max_linear_speed(app, s, r)}

"""PV of the nut (contact pressure times sliding speed) against the nut material's limit."""

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
    load_input,
    where_given,
)
from app.core.phrase import Amount, Phrase


class NutPV(Check):
    name = "pv"
    label = "PV (nut material)"
    description = (
        "A plastic nut heats and wears with pressure times sliding speed; above its PV "
        "limit it fails early. Judged at the peak thrust (an accelerating segment reaches "
        "the top speed still carrying m a) and the top speed."
    )
    quantity = "pv"
    formula = "PV = F_peak / (3 * H_T * h) * (n / 60) * H_T; PV_limit = PV_nut"
    source = "seed catalog, PV Calculation (three threads in contact)"
    sources = ("pv_limit", "root_diameter", "outer_diameter")
    capacity_sources = ("pv_limit",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(where_given(t.pv_limit_pa_m_s), q.pv_pa_m_s, t.pv_limit_pa_m_s)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_peak": q.peak_force_n,
            "H_T": t.helix_travel_m,
            "h": t.thread_depth_m,
            "n": q.rpm,
            "PV_nut": t.pv_limit_pa_m_s,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "PV at the peak thrust, {pv}, " + verb + " the nut limit {limit}.",
            {"pv": Amount(r.pv_pa_m_s, "pv"), "limit": Amount(s.pv_limit_pa_m_s or 0.0, "pv")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "At this speed the load may be at most {load}; at this load the speed may be at "
            "most {speed}." + MARGIN_NOTE,
            {
                "load": Amount(at_most(r.pv_max_load_n), "force"),
                "speed": Amount(at_most(r.pv_max_speed_m_s), "speed"),
            },
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {**load_input(app, r.pv_max_load_n), "speed_m_s": r.pv_max_speed_m_s}

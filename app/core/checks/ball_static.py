"""Ball screw: the peak axial load times the static safety factor against the basic
static load rating C0a."""

import numpy as np

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
    load_input,
    most,
)
from app.core.phrase import Amount, Phrase

#: The leadscrew checks a ball nut has no rating for, named where a ball screw's result
#: is read (their checks do not run for it).
NOT_APPLICABLE_NOTE = (
    " This static rating stands in for the sliding nut's checks, which a rolling ball "
    "nut does not have: the nut PV, flank bearing pressure, sliding speed, nut heat, nut "
    "wear life and design load."
)


class BallStatic(Check):
    name = "ball_static"
    why_none = (
        "the peak thrust exceeds every ball nut's static load rating over the safety "
        "factor: a larger ball screw, a roller screw or a hydraulic cylinder"
    )
    label = "Static load (ball screw)"
    description = (
        "A ball screw's peak axial load (running load plus the force that accelerates or "
        "brakes the moving mass) times the static safety factor f_s (2 by default, THK's "
        "lower limit without vibration or impact; up to 5 with them) against the nut's "
        "basic static load rating C0a, the load that dents the ball track by 0.0001 of the ball "
        "diameter. Applies to ball screws only."
    )
    quantity = "force"
    formula = "F = F_peak * f_s; C0a = C0a_nut"
    source = (
        "THK Ball Screw General Catalog, 'Static Safety Factor', Table 21 (f_s >= 2 without "
        "vibration or impact); C0a from the maker's nut table (HIWIN BS-08-2-EN-1704-K, "
        "sec. 3.7.1 F 3.3)"
    )
    sources = ("static_load",)
    capacity_sources = ("static_load",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(
            t.ball.copy(), q.axis.peak_force_n * app.ball_static_safety_factor, t.static_load_n
        )

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_peak": q.axis.peak_force_n,
            "f_s": app.ball_static_safety_factor,
            "C0a_nut": t.static_load_n,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "within" if passed else "above"
        return Phrase(
            "Peak thrust {f} times the static safety factor {fs} = {demand}, " + verb + " the "
            "nut's static load rating C0a = {c0a}." + NOT_APPLICABLE_NOTE,
            {
                "f": Amount(r.axis.peak_force_n, "force"),
                "fs": Amount(app.ball_static_safety_factor, "factor"),
                "demand": Amount(r.axis.peak_force_n * app.ball_static_safety_factor, "force"),
                "c0a": Amount(s.static_load_n or np.nan, "force"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "Reduce the peak thrust to at most {cap}, or choose a ball nut with a higher "
            "static load rating." + MARGIN_NOTE,
            {"cap": most((s.static_load_n or 0.0) / app.ball_static_safety_factor, "force")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return load_input(app, (s.static_load_n or 0.0) / app.ball_static_safety_factor)

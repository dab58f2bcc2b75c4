"""Ball screw: the load the ball track carries against a fifth of the dynamic load
rating Ca, HIWIN's recommended upper limit of the mean load (advice). It holds whether
or not a duty is given: without one the life is not worked out, and a nut run near Ca
lasts a few kilometres."""

import numpy as np

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
    least,
)
from app.core.duty import track_life_revolutions
from app.core.phrase import Amount, Phrase


class BallLoad(Check):
    name = "ball_load"
    label = "Mean load (ball screw)"
    kind = "advice"
    description = (
        "The load a ball nut's ball track carries (the cycle's cubic mean where a stroke "
        "is given, else the running thrust; in a preloaded nut raised by its preload) "
        "against a fifth of its dynamic load rating Ca, the mean load HIWIN recommends at "
        "most: nearer Ca the rated life is short (at Ca, 10^6 revolutions), whether or "
        "not a duty is given to work it out. Applies to ball screws only."
    )
    quantity = "force"
    formula = "F_m = F_carried; F_max = Ca / 5"
    source = (
        "HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, Table 3.1 (recommended "
        "mean axial load at most Ca / 5); ISO 3408-5 rated life"
    )
    sources = ("dynamic_load", "preload")
    capacity_sources = ("dynamic_load",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(t.ball.copy(), q.life.ball_load_n, t.dynamic_load_n / 5.0)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"F_carried": q.life.ball_load_n, "Ca": t.dynamic_load_n}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        ca, load = s.dynamic_load_n or np.nan, r.life.ball_load_n
        verb = "within" if passed else "above"
        values = {"load": Amount(load, "force"), "ca": Amount(ca, "force")}
        text = "The ball track carries {load}, " + verb + " a fifth of Ca = {ca} (HIWIN's "
        if app.stroke_m or app.moves:  # the life section gives the L10 life over the cycle
            return Phrase(text + "recommended most).", values)
        factor = app.ball_load_factor
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
            (revolutions,) = track_life_revolutions(
                app, np.array([ca]), np.array([s.preload_n or 0.0]), r.axis.force_n, factor
            )
        if not np.isfinite(revolutions):  # no load, or one so small the life overflows
            return Phrase(text + "recommended most).", values)
        values["km"] = Amount(float(revolutions) * s.lead_m, "travel")
        values["fw"] = Amount(factor, "factor")
        text += (
            "recommended most); its rated life there is {km} of travel (L10 at the load "
            "factor {fw}; a stroke and a duty give it in years)."
        )
        return Phrase(text, values)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "A ball nut with Ca of at least {ca} (a larger size, more ball circuits), or a "
            "lighter load or acceleration.",
            {"ca": least(5.0 * r.life.ball_load_n, "force")},
        )

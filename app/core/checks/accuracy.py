"""Worst-case positioning error over the stroke against the user's tolerance."""

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
    same,
    where_given,
)
from app.core.duty import REFERENCE_TEMPERATURE_C
from app.core.formulas import accuracy
from app.core.phrase import Amount, Phrase


class Accuracy(Check):
    name = "accuracy"
    label = "Positioning accuracy"
    description = (
        "Lead error over the stroke (a leadscrew's lead accuracy times the stroke; a ball "
        "screw's limit deviation e_p of its ISO 3408-3 tolerance class over the stroke), "
        "plus the screw's thermal growth over the stroke (its material's expansion, the "
        "screw taken at the ambient against the 20 °C reference; its own friction heat is "
        "not counted), plus the largest backlash, plus repeatability, summed as a worst "
        "case, against the tolerance."
    )
    quantity = "length"
    formula = "e = e_lead + alpha * stroke * abs(T_ambient - T_ref) + b_max + r; e_allowed = tol"
    source = (
        "seed catalog, Screw Accuracy; ISO 3408-3 and HIWIN BS-08-2-EN-1704-K sec. 3.5.3 "
        "(a ball screw's e_p by useful travel); thermal growth dL = alpha L dT (ASM "
        "Handbook expansion); THK Ball Screw, Point of Selection: Studying the Positioning "
        "Accuracy (thermal displacement a cause of error beside the lead accuracy and the "
        "clearance)"
    )
    # a ball screw's lead accuracy is its class's v300p, with its maker's e_p table
    # (``travel_deviation``) where it is a positioning class
    sources = ("lead_accuracy", "backlash", "repeatability", "screw_expansion")
    needs = ("lead_accuracy", "backlash")  # a missing repeatability counts as none

    def applies(self, app: Application) -> bool:
        return app.positioning_tolerance_m is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        error = accuracy.worst_case_error(
            q.accuracy.lead_error_m,
            q.accuracy.thermal_growth_m,
            t.backlash_max_m,
            t.repeatability_m,
        )
        tolerance = same(t, app.positioning_tolerance_m)
        # judged where the lead error and the nut's play are given (a screw of one's own
        # has neither)
        given = where_given(q.accuracy.lead_error_m) & where_given(t.backlash_max_m)
        return Measure(given, np.asarray(error), tolerance)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "e_lead": q.accuracy.lead_error_m,
            "stroke": app.stroke_m if app.stroke_m is not None else app.length_m,
            "alpha": t.screw_expansion_per_k,
            "T_ambient": app.ambient_c,
            "T_ref": REFERENCE_TEMPERATURE_C,
            "b_max": t.backlash_max_m,
            "r": t.repeatability_m,
            "tol": app.positioning_tolerance_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        repeatability = s.repeatability_m or 0.0
        backlash = s.backlash_max_m or 0.0  # judged only where given (``measure``)
        error = accuracy.worst_case_error(
            r.accuracy.lead_error_m, r.accuracy.thermal_growth_m, backlash, repeatability
        )
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "Worst-case error {e} (lead error {lead} + thermal growth {growth} + backlash "
            "{b} + repeatability {r}) " + verb + " the {tol} tolerance. The growth takes the "
            "screw at the {ambient} ambient, {dt} from the {ref} reference; its own friction "
            "heat is not counted.",
            {
                "e": Amount(error, "length"),
                "lead": Amount(r.accuracy.lead_error_m, "length"),
                "growth": Amount(abs(r.accuracy.thermal_growth_m), "length"),
                "b": Amount(backlash, "length"),
                "r": Amount(repeatability, "length"),
                "tol": Amount(app.positioning_tolerance_m or 0.0, "length"),
                "ambient": Amount(app.ambient_c, "temperature"),
                "dt": Amount(abs(app.ambient_c - REFERENCE_TEMPERATURE_C), "temperature_rise"),
                "ref": Amount(REFERENCE_TEMPERATURE_C, "temperature"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        thermal = (
            " or hold the screw nearer the {ref} reference (its growth is {growth})"
            if r.accuracy.thermal_growth_m
            else ""
        )
        values = {
            "ref": Amount(REFERENCE_TEMPERATURE_C, "temperature"),
            "growth": Amount(abs(r.accuracy.thermal_growth_m), "length"),
        }
        if s.anti_backlash or not reach.anti_backlash:
            return Phrase(
                "Choose a precision lead grade" + thermal + ", or widen the tolerance.", values
            )
        return Phrase(
            "Choose an anti-backlash series (no backlash) or a precision lead grade"
            + thermal
            + ".",
            values,
        )

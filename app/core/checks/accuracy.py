"""Worst-case positioning error over the stroke against the user's tolerance."""

import math

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
    everywhere,
    same,
)
from app.core.duty import REFERENCE_TEMPERATURE_C
from app.core.formulas import accuracy
from app.core.phrase import Amount, Phrase
from app.core.wording import value_label


def _known(value: float | None) -> bool:
    """A value the catalog gives: neither None nor NaN."""
    return value is not None and not math.isnan(value)


#: The catalog values the growth from the friction heat reads beyond the thread's: the
#: screw's field and its catalog key (named by ``wording.value_label``).
_HEAT_VALUES = (
    ("nut_length_m", "nut_length"),
    ("thermal_conductivity_w_m_k", "thermal_conductivity"),
    ("screw_expansion_per_k", "screw_expansion"),
)


def _heat_words(app: Application, s: ScrewSpec, counted: bool) -> str:
    """The accuracy sentence's words on the screw's growth from its nut's friction heat
    (``duty.heat_growth``): the nut's rise and the span it is counted over with what that
    assumes, else why it is not counted."""
    if counted:
        return (
            "; the nut's friction heat (the nut {rise} above the ambient) grows it {heat} "
            "more from the thrust bearing to the nut's middle at the far end of the stroke. "
            "Assumed: the thrust bearing at the screw's end, the screw cooling from the nut "
            "as the nut-heat check's fin, insulated at that end (a bearing nearer the nut, "
            "or drawing heat off, grows it less)."
        )
    if s.screw_type == "ball":
        why = "a ball nut rolls, and the heat model is a sliding nut's"
    elif not (app.stroke_m or app.moves):
        why = "without a stroke there is no duty to heat it"
    else:
        lacks = [value_label(key) for attr, key in _HEAT_VALUES if getattr(s, attr) is None]
        why = "the catalog does not give the " + (
            " or the ".join(lacks) if lacks else "values its heat balance reads"
        )
        why += " for this screw"
    return "; its own friction heat is not counted: " + why + "."


class Accuracy(Check):
    name = "accuracy"
    label = "Positioning accuracy"
    description = (
        "Lead error over the stroke (the screw length where no stroke is given: a "
        "leadscrew's lead accuracy times it; a ball screw's limit deviation e_p of its "
        "ISO 3408-3 tolerance class over it), "
        "plus the screw's thermal growth over the stroke (its material's expansion, the "
        "screw taken at the ambient against the 20 °C reference), plus its growth from "
        "the nut's friction heat (with a stroke, a sliding nut: the nut-heat check's "
        "rise and its fin profile along the screw, integrated from the thrust bearing, "
        "taken at the screw's end, to the nut's middle at the far end of the stroke; "
        "not counted without a duty, on a ball nut or where the heat balance lacks a "
        "value), plus the largest backlash, plus repeatability, summed as a worst "
        "case, against the tolerance. A term the catalog does not give for the screw (no "
        "lead accuracy, no backlash) is left out and the result says so: the known terms "
        "alone over the tolerance fail it."
    )
    quantity = "length"
    formula = (
        "e = e_lead + alpha * stroke * abs(T_ambient - T_ref) + dL_heat + b_max + r; "
        "e_allowed = tol"
    )
    source = (
        "seed catalog, Screw Accuracy; ISO 3408-3 and HIWIN BS-08-2-EN-1704-K sec. 3.5.3 "
        "(a ball screw's e_p by useful travel); thermal growth dL = alpha L dT (ASM "
        "Handbook expansion); THK Ball Screw, Point of Selection: Studying the Positioning "
        "Accuracy (thermal displacement a cause of error beside the lead accuracy and the "
        "clearance, dL = alpha times the integral of the screw's rise); Incropera sec. 3.6, "
        "Table 3.4 case B (the fin's temperature profile)"
    )
    # a ball screw's lead accuracy is its class's v300p, with its maker's e_p table
    # (``travel_deviation``) where it is a positioning class
    sources = (
        "lead_accuracy",
        "backlash",
        "repeatability",
        "screw_expansion",
        "thermal_conductivity",
        "friction_dynamic",
    )

    def applies(self, app: Application) -> bool:
        return app.positioning_tolerance_m is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        # every screw is judged on the terms it has: a lead error or a backlash the
        # catalog does not give counts as none, and the result says it is left out
        error = accuracy.worst_case_error(
            np.nan_to_num(q.accuracy.lead_error_m),
            q.accuracy.thermal_growth_m,
            np.nan_to_num(t.backlash_max_m),
            t.repeatability_m,
            np.nan_to_num(q.accuracy.heat_growth_m),
        )
        return Measure(everywhere(t), np.asarray(error), same(t, app.positioning_tolerance_m))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "e_lead": np.nan_to_num(q.accuracy.lead_error_m),
            "stroke": app.stroke_m if app.stroke_m is not None else app.length_m,
            "alpha": t.screw_expansion_per_k,
            "T_ambient": app.ambient_c,
            "T_ref": REFERENCE_TEMPERATURE_C,
            "dL_heat": np.nan_to_num(q.accuracy.heat_growth_m),
            "b_max": np.nan_to_num(t.backlash_max_m),
            "r": t.repeatability_m,
            "tol": app.positioning_tolerance_m,
        }

    def left_out(self, app: Application, s: ScrewSpec, r: Quantities[float]) -> tuple[str, ...]:
        """The lead accuracy where the screw's lead error over the stroke is not given,
        the backlash where its nut's is not."""
        gaps = {
            "lead_accuracy": _known(r.accuracy.lead_error_m),
            "backlash": s.backlash_max_m is not None,
        }
        return tuple(name for name, given in gaps.items() if not given)

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        repeatability = s.repeatability_m or 0.0
        lead, backlash = r.accuracy.lead_error_m, s.backlash_max_m
        heated = r.accuracy.heat_growth_m
        has_lead, has_play, has_heat = _known(lead), backlash is not None, _known(heated)
        terms = (
            ("lead error {lead}", has_lead),
            ("thermal growth {growth}", True),
            ("friction-heat growth {heat}", has_heat),
            ("backlash {b}", has_play),
            ("repeatability {r}", True),
        )
        known = " + ".join(text for text, given in terms if given)
        gaps = (("lead error", has_lead), ("backlash", has_play))
        missing = " and ".join(words for words, given in gaps if not given)
        error = accuracy.worst_case_error(
            lead if has_lead else 0.0,
            r.accuracy.thermal_growth_m,
            backlash or 0.0,
            repeatability,
            heated if has_heat else 0.0,
        )
        verb = "is within" if passed else "exceeds"
        head = "Worst-case error {e} (" + known + ") " + verb + " the {tol} tolerance"
        if missing:
            without = ", leaving out the " if passed else " even without the "
            head = (
                "Worst-case error {e} of the known terms ("
                + known
                + ") "
                + verb
                + " the {tol} tolerance"
                + without
                + missing
                + ", which the catalog does not give for this screw"
            )
        return Phrase(
            head + ". The growth takes the screw at the {ambient} ambient, {dt} from the {ref} "
            "reference" + _heat_words(app, s, has_heat),
            {
                "e": Amount(error, "length"),
                "lead": Amount(lead if has_lead else 0.0, "length"),
                "growth": Amount(abs(r.accuracy.thermal_growth_m), "length"),
                "heat": Amount(heated if has_heat else 0.0, "length"),
                "rise": Amount(r.heat.nut_temperature_rise_k, "temperature_rise"),
                "b": Amount(backlash or 0.0, "length"),
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
        heated = r.accuracy.heat_growth_m
        if _known(heated) and heated > 0.0:
            thermal += (
                " or run the nut cooler (its friction heat grows the screw {heat}: longer "
                "dwells, a lower speed or a lower-friction nut)"
            )
        values = {
            "ref": Amount(REFERENCE_TEMPERATURE_C, "temperature"),
            "growth": Amount(abs(r.accuracy.thermal_growth_m), "length"),
            "heat": Amount(heated if _known(heated) else 0.0, "length"),
        }
        # a finer lead grade cannot help where the lead error is not counted at all
        grade = "a precision lead grade" if _known(r.accuracy.lead_error_m) else ""
        if s.anti_backlash or not reach.anti_backlash:
            if not grade:
                return Phrase("Widen the tolerance" + thermal + ".", values)
            return Phrase("Choose " + grade + thermal + ", or widen the tolerance.", values)
        series = "an anti-backlash series (no backlash)"
        choices = " or ".join(c for c in (series, grade) if c)
        return Phrase("Choose " + choices + thermal + ".", values)

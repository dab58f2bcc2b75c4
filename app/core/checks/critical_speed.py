"""Screw speed against the allowed fraction of its first whirling speed."""

import math

import numpy as np

from app.core import motion
from app.core.checks.base import (
    MARGIN_NOTE,
    Application,
    Array,
    CandidateTable,
    Check,
    EndFixity,
    Mapping,
    Measure,
    Quantities,
    Reach,
    ScrewSpec,
    at_least,
    at_most,
    everywhere,
    least,
    most,
    run_at_most,
    sentence,
    stiffer_fixity,
)
from app.core.formulas import critical_speed, geometry
from app.core.input_rules import least_inputs
from app.core.phrase import Amount, Phrase


class CriticalSpeed(Check):
    name = "critical_speed"
    slower_may_clear = True
    why_none = (
        "the speed needs a critical-speed margin no screw of this length reaches, at any "
        "mounting: consider a ball screw, a rotating nut or an intermediate screw support"
    )
    why_none_ball = (
        "the speed needs a critical-speed margin no ball screw of this length reaches, at "
        "any mounting: consider a rotating nut, an intermediate screw support or a belt"
    )
    label = "Critical speed"
    description = (
        "A long thin screw whirls when it turns near its first bending frequency; the "
        "allowed speed is a fraction (the critical-speed factor) of that speed."
    )
    quantity = "rpm"
    formula = (
        "n = 60 * v / lead; "
        "n_allowed = SF * min(60 / (2 * pi) * min(beta^2, C_s * pi^2) / L^2 * sqrt(E / rho) "
        "* d_r / 4, n_T, n_H)"
    )
    source = (
        "Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1; at most Thomson's "
        "and Roton's end fixity factor C_s times simple-simple (for a ball screw too, as "
        "Rockford Ball Screw rates its own, unless its maker rates it by HIWIN's rule); a "
        "ball screw at most HIWIN BS-08-2-EN-1704-K F 3.27 (n_H); likewise at most "
        "Thomson's C_s x 4.76e6 d_r / L^2 [rpm, in] (n_T, its constant a steel's)"
    )
    sources = ("root_diameter", "youngs_modulus", "density")
    capacity_sources = ("root_diameter", "youngs_modulus", "density")

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.axis.rpm, q.column.allowed_rpm)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        hiwin_rated = t.ball & t.hiwin_speed  # rated by HIWIN's rule alone
        return {
            "v": motion.reached_speed(app),
            "lead": t.lead_m,
            "SF": app.critical_speed_safety_factor,
            "beta": critical_speed.END_FIXITY_BETA[app.end_fixity],
            "L": app.length_m,
            "E": t.youngs_modulus_pa,
            "rho": t.density_kg_m3,
            "d_r": t.root_diameter_m,
            # at most the leadscrew makers' C_s times simple-simple (pi^2), but a ball screw
            # its maker rates by HIWIN's rule; a ball screw at most HIWIN's F 3.27 too
            "C_s": np.where(
                hiwin_rated, np.inf, critical_speed.LEADSCREW_FIXITY_FACTOR[app.end_fixity]
            ),
            # Thomson's C_s 4.76e6 d_r / L^2 [rpm, in], where C_s holds
            "n_T": np.where(
                hiwin_rated,
                np.inf,
                critical_speed.leadscrew_makers_critical_speed_rpm(
                    t.root_diameter_m, app.length_m, app.end_fixity
                ),
            ),
            "n_H": np.where(
                t.ball,
                critical_speed.ball_screw_critical_speed_rpm(
                    t.root_diameter_m, app.length_m, app.end_fixity
                ),
                np.inf,
            ),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is below" if passed else "exceeds"
        values: dict[str, Amount | str] = {
            "n": Amount(r.axis.rpm, "rpm"),
            "allowed": Amount(r.column.allowed_rpm, "rpm"),
            "sf": Amount(app.critical_speed_safety_factor, "factor"),
            "n_c": Amount(r.column.critical_rpm, "rpm"),
            "fixity": app.end_fixity,
        }
        text = "{n} " + verb + " the allowed {allowed} ({sf} x critical {n_c}, {fixity})."
        beam = critical_speed.critical_speed_rpm(
            s.root_diameter_m, app.length_m, s.youngs_modulus_pa, s.density_kg_m3,
            app.end_fixity,
        )  # fmt: skip
        ratio = r.column.critical_rpm / beam
        if s.screw_type == "ball" and _hiwin_governs(app, s, r.column.critical_rpm):
            values["lower"] = f"{(1.0 - ratio) * 100.0:.1f} %"
            text += (
                " HIWIN rates it (F 3.27, its mounting factor for these ends) {lower} "
                "below the beam's."
            )
            return Phrase(text, values)
        below = ratio < 1.0 and not math.isclose(ratio, 1.0)
        if not below or s.critical_speed_rule == critical_speed.HIWIN_RULE:
            return Phrase(text, values)
        # leadscrew makers' tables rate these ends below the beam: the rating is theirs
        factor = f"{critical_speed.LEADSCREW_FIXITY_FACTOR[app.end_fixity]:g}"
        table = critical_speed.makers_table_ratio(app.end_fixity)
        if ratio < table and not math.isclose(ratio, table):
            # the screw's steel is stiffer or lighter than Thomson's constant is worked with
            factor += " (at most Thomson's 4.76e6 d_r / L^2 [rpm, in])"
        values["cs"] = factor
        values["lower"] = f"{(1.0 - ratio) * 100.0:.1f} %"
        makers = "leadscrew makers' (Thomson, Roton)"
        if s.screw_type == "ball":  # its family names no maker's rule: the lowest published
            makers = "lowest published rule, the makers' (Thomson, Roton, Rockford)"
        text += (
            " Its critical speed is the " + makers + " for these ends: C_s {cs} times "
            "simple-simple, {lower} below the beam's."
        )
        return Phrase(text, values)

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        def allowed(fixity: EndFixity) -> float:
            n_c = critical_speed.rated_critical_speed_rpm(
                s.root_diameter_m, app.length_m, s.youngs_modulus_pa, s.density_kg_m3, fixity,
                s.screw_type == "ball",
                hiwin_rated=s.critical_speed_rule == critical_speed.HIWIN_RULE,
            )  # fmt: skip
            return critical_speed.allowed_speed_rpm(float(n_c), app.critical_speed_safety_factor)

        lead = critical_speed.min_lead_for_speed(motion.reached_speed(app), r.column.allowed_rpm)
        d_min = critical_speed.min_root_diameter_for_speed(
            s.root_diameter_m, r.column.allowed_rpm, r.axis.rpm
        )
        options = []
        values: dict[str, Amount | str] = {
            "length": most(_max_length(app, r), "length"),
            "fixity": app.end_fixity,
        }
        made = reach.made_lead(s, at_least(lead), larger=True)
        if made is not None and made <= reach.max_lead_m:
            options.append("a lead of at least {lead}")
            values["lead"] = Amount(made, "length")
        if at_least(d_min) <= reach.max_root_diameter_m:
            options.append("a root diameter of at least {d}")
            values["d"] = least(d_min, "length")
        # a stiffer mounting is offered only when it keeps the margin at this length
        stiffer = stiffer_fixity(app, lambda f: at_least(r.axis.rpm) <= allowed(f))
        if stiffer is None:
            options.append(
                "add an intermediate support (unsupported length at most {length} with the "
                "ends {fixity})"
            )
        else:
            length = critical_speed.max_length_for_speed(app.length_m, allowed(stiffer), r.axis.rpm)
            values["stiffer"] = stiffer
            values["stiffer_length"] = most(length, "length")
            options.append(
                "mount the ends {stiffer} (unsupported length at most {stiffer_length} with "
                "the ends {stiffer})"
            )
            # a length shorter than the stroke (or the span to the thrust bearing) is no
            # screw the inputs accept: then the stroke keeps its length over a support
            shortest = least_inputs(app).get("length_m")
            if shortest is not None and at_most(_max_length(app, r)) < shortest:
                options.append(
                    "add an intermediate support (unsupported length at most {length} with "
                    "the ends {fixity})"
                )
            else:
                options.append("an unsupported length of at most {length} with the ends {fixity}")
        speed = geometry.linear_speed(r.column.allowed_rpm, s.lead_m)
        values["speed"] = most(speed, "speed")
        options.append(run_at_most(app).lower() + " {speed}")
        use = "Use " if options[0].startswith("a ") else ""
        return sentence(use + ", or ".join(options) + "." + MARGIN_NOTE, values)

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {
            "speed_m_s": geometry.linear_speed(r.column.allowed_rpm, s.lead_m),
            "length_m": _max_length(app, r),
        }


def _max_length(app: Application, r: Quantities[float]) -> float:
    """Longest unsupported length at which this screw's speed is allowed [m]."""
    return critical_speed.max_length_for_speed(app.length_m, r.column.allowed_rpm, r.axis.rpm)


def _hiwin_governs(app: Application, s: ScrewSpec, critical_rpm: float) -> bool:
    """Whether a ball screw's critical speed ``critical_rpm`` is HIWIN's rule (F 3.27),
    below the beam's (``rated_critical_speed_rpm``)."""
    hiwin = critical_speed.ball_screw_critical_speed_rpm(
        s.root_diameter_m, app.length_m, app.end_fixity
    )
    return math.isclose(critical_rpm, float(hiwin))

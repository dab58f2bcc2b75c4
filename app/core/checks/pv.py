"""PV of the nut (contact pressure times sliding speed) against the nut material's limit."""

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
    allowed_load,
    load_input,
    most,
)
from app.core.formulas import pv_derating
from app.core.phrase import Amount, Phrase


class NutPV(Check):
    name = "pv"
    slower_may_clear = True
    judged_instead_by = "bearing_pressure"
    why_none = (
        "no nut carries this load at this speed (PV): consider a ball screw, whose rolling "
        "contact has no PV limit"
    )
    label = "PV (nut material)"
    description = (
        "A plastic nut heats and wears with pressure times sliding speed; above its PV "
        "limit it fails early. Judged at the peak thrust (an accelerating segment reaches "
        "the top speed still carrying m a) and the top speed; in a cycle of moves, at each "
        "move's own, the move whose thrust times speed is largest. The limit is the nut's "
        "rating derated in a straight line from the 20 °C rating to nothing at the "
        "material's highest temperature, at the ambient (its own friction heat is the PV "
        "itself; the nut heat check judges the rise), times a factor for its lubrication."
    )
    quantity = "pv"
    formula = "PV = F_peak / (3 * H_T * h) * (n / 60) * H_T; PV_limit = PV_nut * f_T * f_lub"
    source = (
        "seed catalog, PV Calculation (three threads in contact); PV derated with the "
        "ambient as igus's permitted pv, proportional to T_max - T_ambient, lubrication "
        "factors igus Table 1.4 and BNB (formulas.pv_derating)"
    )
    sources = ("pv_limit", "root_diameter", "outer_diameter", "temperature_range")
    capacity_sources = ("pv_limit",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(t.pv_limit_given, q.nut.pv_pa_m_s, q.nut.pv_limit_pa_m_s)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_peak": q.nut.pv_force_n,
            "H_T": t.helix_travel_m,
            "h": t.thread_depth_m,
            "n": q.nut.pv_rpm,
            "PV_nut": t.pv_limit_pa_m_s,
            "T_ambient": np.full(len(t), app.ambient_c),
            "T_max": t.temperature_max_c,
            "f_T": q.nut.pv_temperature_factor,
            "f_lub": q.nut.pv_lubrication_factor,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        at: dict[str, Amount | str | Phrase] = {}
        if app.moves:  # each move at its own thrust and speed
            at = {"thrust": Amount(r.nut.pv_force_n, "force"), "n": Amount(r.nut.pv_rpm, "rpm")}
        where = "the peak thrust" if not at else "the move that loads it most, {thrust} at {n}"
        return Phrase(
            "PV at " + where + ", {pv}, " + verb + " the nut limit {limit}: its rating "
            "{rating} {derated}.",
            {
                **at,
                "pv": Amount(r.nut.pv_pa_m_s, "pv"),
                "limit": Amount(r.nut.pv_limit_pa_m_s, "pv"),
                "rating": Amount(s.pv_limit_pa_m_s or 0.0, "pv"),
                "derated": derating(app, s, r),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if not r.nut.pv_limit_pa_m_s > 0:  # derated to nothing: no load or speed is within it
            return no_pv_left(app, r)
        load = allowed_load(app, r.nut.pv_max_load_n, "thrust")
        return Phrase(
            "At this speed " + load.template + "; at this load the speed may be at most "
            "{speed}." + MARGIN_NOTE,
            {**load.values, "speed": most(r.nut.pv_max_speed_m_s, "speed")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        if not r.nut.pv_limit_pa_m_s > 0:
            return {}
        return {**load_input(app, r.nut.pv_max_load_n), "speed_m_s": r.nut.pv_max_speed_m_s}


def no_pv_left(app: Application, r: Quantities[float]) -> Phrase:
    """The fix where the nut's PV is derated to nothing at the ambient: no load or speed
    is then within it."""
    return Phrase(
        "At {temp} around it the nut has no PV left (its material's highest "
        "temperature), and lubrication cannot add to nothing: choose a nut material rated "
        "hotter, or cool the nut's surroundings.",
        {"temp": Amount(app.ambient_c, "temperature")},
    )


def derating(app: Application, s: ScrewSpec, r: Quantities[float]) -> Phrase:
    """How a PV rating is derated: the temperature factor at the ambient, with the line
    it is read from, and the lubrication factor, with its provenance and source."""
    counted = app.lubrication_counted
    _, kind, source = pv_derating.LUBRICATION_FACTORS[counted]
    lost = (
        f" (the {app.lubrication} nut's lubricant evaporates in a vacuum)"
        if counted != app.lubrication
        else ""
    )
    values: dict[str, Amount | str] = {
        "f_t": f"{r.nut.pv_temperature_factor:.2f}",
        "temp": Amount(app.ambient_c, "temperature"),
        "f_lub": f"{r.nut.pv_lubrication_factor:.2f}",
        "lub": f"{counted}{lost}, {kind}: {source}",
    }
    line = ""
    if s.temperature_max_c is not None and s.temperature_max_c > pv_derating.REFERENCE_C:
        line = " (igus: straight from the {ref} rating to none at the material's {t_max})"
        values["ref"] = Amount(pv_derating.REFERENCE_C, "temperature")
        values["t_max"] = Amount(s.temperature_max_c, "temperature")
    return Phrase(
        "times {f_t} at the ambient {temp}" + line + " and {f_lub} for its lubrication ({lub})",
        values,
    )

"""Contact pressure on the engaged flanks of a sliding nut against the pressure its
material allows at the sliding speed (bronze by a table, polymers by p_max and PV)."""

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
    where_given,
)
from app.core.checks.pv import derating, no_pv_left
from app.core.phrase import Amount, Phrase


class BearingPressure(Check):
    name = "bearing_pressure"
    slower_may_clear = True
    judged_instead_by = "pv"
    why_none = (
        "no nut carries this thrust at its contact pressure: consider a longer nut or a ball screw"
    )
    label = "Nut contact pressure"
    description = (
        "The peak thrust (load and m a) spread over the engaged flanks of the nut (nut "
        "length over pitch turns of pi d2 H1 each) against the contact pressure the nut "
        "material allows at the sliding speed: a bronze nut by its pressure-speed "
        "table, a polymer nut by its maximum pressure and its PV limit, derated to the "
        "ambient and raised for its lubrication as in the PV check. In a cycle of moves, "
        "each move's peak thrust at its own speed, the move the nut carries worst."
    )
    quantity = "force"
    formula = "F = F_peak; F_allow = p_nut_v * L_nut / P * pi * d_2 * H_1"
    source = (
        "Shigley, power-screw bearing stress over the engaged turns; Shigley Table 8-4 "
        "(after Rothbart) for bronze; the nut material's p_max and PV (catalog), the PV "
        "derated with the nut temperature and lubrication (formulas.pv_derating)"
    )
    sources = ("bearing_pressure", "max_pressure", "bearing_pv_limit", "nut_length", "pitch")
    capacity_sources = ("bearing_pressure", "max_pressure", "bearing_pv_limit", "nut_length")

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(
            where_given(q.nut.nut_allowed_load_n), q.nut.bearing_force_n, q.nut.nut_allowed_load_n
        )

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_peak": q.nut.bearing_force_n,
            "p_nut_v": q.nut.nut_allowed_pressure_pa,
            "L_nut": q.nut.nut_length_m,
            "P": t.pitch_m,
            "d_2": t.flank_pitch_diameter_m,
            "H_1": t.flank_height_m,
            "v": q.nut.bearing_sliding_speed_m_s,
            "p_max": t.max_pressure_pa,
            "PV_nut": t.nut_pv_limit_pa_m_s,
            "f_T": q.nut.pv_temperature_factor,
            "f_lub": q.nut.pv_lubrication_factor,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        values: dict[str, Amount | str | Phrase] = {
            "f": Amount(r.nut.bearing_force_n, "force"),
            "cap": Amount(r.nut.nut_allowed_load_n, "force"),
            "v": Amount(r.nut.bearing_sliding_speed_m_s, "speed"),
            "p": Amount(r.nut.nut_allowed_pressure_pa, "pressure"),
            "why": _slower(app, s, r),
        }
        return Phrase(
            "The peak thrust {f} " + verb + " the load {cap} that the nut's engaged "
            "flanks carry at the sliding speed {v}, where the nut material allows {p}{why}.",
            values,
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if not r.nut.nut_allowed_load_n > 0 and r.nut.pv_temperature_factor == 0.0:
            return no_pv_left(app, r)
        load = allowed_load(app, r.nut.nut_allowed_load_n)
        return Phrase(
            "At this speed " + load.template + "; a longer nut, a larger size or a nut "
            "material that allows more pressure carries more." + MARGIN_NOTE,
            dict(load.values),
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        if not r.nut.nut_allowed_load_n > 0:
            return {}
        return load_input(app, r.nut.nut_allowed_load_n)


def _slower(app: Application, s: ScrewSpec, r: Quantities[float]) -> Phrase:
    """Why the allowable pressure is below the material's slow-sliding one, when it is:
    the flanks slide faster than its table's first row (a larger size, at the same speed
    of turning, slides faster: it may carry less although its flank area is larger), or
    its PV limit binds. Empty when the slow-sliding pressure holds."""
    table = s.bearing_pressure_table
    slow = [p for p in (table[0][1] if table else None, s.max_pressure_pa) if p is not None]
    if not slow or r.nut.nut_allowed_pressure_pa >= min(slow):
        return Phrase("")
    values: dict[str, Amount | str | Phrase] = {"p0": Amount(min(slow), "pressure")}
    if table and r.nut.bearing_sliding_speed_m_s > table[0][0]:
        values["v0"] = Amount(table[0][0], "speed")
        return Phrase(
            ", less than the {p0} it allows up to {v0}: the allowable pressure falls as the "
            "flanks slide faster, and a larger size slides faster at the same speed of "
            "turning, so it may carry less although its flanks are larger",
            values,
        )
    values["pv"] = Amount(r.nut.nut_pv_limit_pa_m_s, "pv")
    values["derated"] = derating(app, s, r)
    return Phrase(
        ", less than its {p0} at slow sliding: its PV limit {pv} (the rating {derated}) "
        "binds at this speed, and a "
        "larger size slides faster at the same speed of turning",
        values,
    )

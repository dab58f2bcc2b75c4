"""The nut's temperature from its friction heat against the nut's rated maximum: a heat
balance of the thread's friction power and the nut's drag power with the screw (a fin
both ways) and the nut's surface."""

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
    most,
    where_given,
)
from app.core.duty import stroke_span_m
from app.core.formulas import heat
from app.core.phrase import Amount, Phrase


def headroom(app: Application, t: CandidateTable) -> Array:
    """The nut's rated maximum less the ambient [K]: 0 at the ambient of the rating
    itself (which the temperature check passes), NaN where there is none (no rating, or
    the ambient above it: the temperature check fails it)."""
    room = t.temperature_max_c - app.ambient_c
    return np.where(room >= 0.0, room, np.nan)


def unchecked_note(app: Application, sliding_passes: bool) -> Phrase | None:
    """Without a stroke, where a sliding nut passes: that its heat is not checked (the
    heat depends on the duty, the moves and their dwells, which are not given) and what
    to give to check it (None otherwise)."""
    if NutHeat().applies(app) or not sliding_passes:
        return None
    return Phrase("Nut heat is not checked without a stroke: give one to judge it.")


class NutHeat(Check):
    name = "nut_heat"
    slower_may_clear = True
    why_none = "every nut runs too hot at this duty: a ball screw, or a lower duty"
    label = "Nut heat"
    description = (
        "With a stroke (the duty: moves and dwells), the thread's friction power at the "
        "cycle's mean speed, F v (1 / eta - 1) with F the thrust the thread carries over "
        "the cycle (the load, the weight on a vertical axis and m a on the ramps, weighted "
        "by each segment's travel), and the drag power of a preloaded (anti-backlash) "
        "nut, T_drag 2 pi v / lead, heat "
        "the nut until the screw (conducting both ways, a fin of its root diameter and "
        "material each side of the nut, its far end taken as insulated, the nut at the "
        "end of a stroke centred on the screw, where its fins conduct least) and the "
        "nut's surface (free convection, 10 W/(m^2 K)) carry it away: the nut's rise over "
        "the ambient against the room to its rated maximum temperature."
    )
    quantity = "temperature_rise"
    formula = (
        "dT = (F * v * (1 / eta - 1) + T_drag * 2 * pi * v / lead) / "
        "(sqrt(h * pi * d_3 * k * pi * d_3^2 / 4) * "
        "(tanh(sqrt(4 * h / (k * d_3)) * max(0, (L - s - L_nut) / 2)) + "
        "tanh(sqrt(4 * h / (k * d_3)) * max(0, L - L_nut - max(0, (L - s - L_nut) / 2)))) "
        "+ h * pi * D_nut * L_nut); "
        "dT_allowed = T_max - T_ambient"
    )
    source = (
        "Incropera, Fundamentals of Heat and Mass Transfer, sec. 3.6 (Table 3.4, a fin "
        "with an adiabatic tip) and "
        "Table 1.1 (free convection); Shigley sec. 8-2 (thread efficiency)"
    )
    sources = (
        "thermal_conductivity",
        "friction_dynamic",
        "drag_torque",
        "nut_length",
        "temperature_range",
    )
    capacity_sources = ("temperature_range",)
    #: the heat balance needs the screw's conductivity (its fin) as well as the nut's
    #: rated temperature: a screw without either is named as not checked
    needs = ("thermal_conductivity", "temperature_range")

    def applies(self, app: Application) -> bool:
        # the heat depends on the duty: without a stroke (and its dwells) there is none
        return bool(app.stroke_m or app.moves)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        room = headroom(app, t)
        rise = q.heat.nut_temperature_rise_k
        # a ball nut rolls: no sliding-friction heat balance
        applicable = where_given(rise) & where_given(room) & ~t.ball
        return Measure(applicable, rise, room)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F": q.life.wear_force_n,
            "v": q.heat.heat_speed_m_s,
            "eta": t.efficiency,
            "T_drag": t.drag_max_nm,
            "lead": t.lead_m,
            "h": heat.FREE_CONVECTION_W_M2_K,
            "d_3": t.root_diameter_m,
            "k": t.thermal_conductivity_w_m_k,
            "D_nut": heat.NUT_OUTER_TO_D * t.outer_diameter_m,
            "L_nut": q.nut.nut_length_m,
            "L": app.length_m,
            "s": stroke_span_m(app),
            "T_max": t.temperature_max_c,
            "T_ambient": app.ambient_c,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "within" if passed else "above"
        # a nut without preload has no drag: its sentence names the thread's friction alone
        dragged = r.heat.drag_power_w > 0.0
        drag: dict[str, Amount | str] = (
            {"drag": Amount(r.heat.drag_power_w, "power")} if dragged else {}
        )
        return Phrase(
            "Friction turns {power} into heat"
            + (" and the nut's drag {drag} more" if dragged else "")
            + ": the nut runs {rise} above the ambient, at {nut}, "
            + verb
            + " its rated {limit}. Assumed: free convection of {h} "
            "W/(m² K) (still air gives 2-25: less runs the nut hotter) and a round nut "
            "{nut_d} times the thread's diameter.",
            {
                "power": Amount(r.heat.friction_power_w, "power"),
                **drag,
                "rise": Amount(r.heat.nut_temperature_rise_k, "temperature_rise"),
                "nut": Amount(app.ambient_c + r.heat.nut_temperature_rise_k, "temperature"),
                "limit": Amount(s.temperature_max_c or 0.0, "temperature"),
                "h": f"{heat.FREE_CONVECTION_W_M2_K:g}",
                "nut_d": f"{heat.NUT_OUTER_TO_D:g}",
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        drag = ", a nut of less drag (less preload)" if r.heat.drag_power_w > 0.0 else ""
        # the heat is linear in the cycle's mean speed: the rise falls with it to the room
        room = (s.temperature_max_c or np.nan) - app.ambient_c
        if room <= 0.0:
            return Phrase(
                "The ambient {t} is the nut's rated maximum: any motion heats it above. A "
                "nut rated hotter or a cooler ambient.",
                {"t": Amount(app.ambient_c, "temperature")},
            )
        mean = r.heat.heat_speed_m_s * room / r.heat.nut_temperature_rise_k
        return Phrase(
            "Less heat or more cooling: longer dwells or a lower speed, for a mean speed "
            "over the cycle (its travel over its time, dwells included) of at most {mean}; "
            "a steeper lead (higher efficiency), a lubricated or lower-friction nut"
            + drag
            + ", a larger screw or a nut rated hotter."
            + MARGIN_NOTE,
            {"mean": most(mean, "speed")},
        )

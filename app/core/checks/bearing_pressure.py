"""Contact pressure on the engaged flanks of a sliding nut against the pressure its
material allows at the sliding speed (bronze by a table, polymers by p_max and PV)."""

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
    load_input,
    per_table,
    table_of,
    where_given,
)
from app.core.formulas import bearing, pv
from app.core.phrase import Amount, Phrase


def sliding_speed(rpm: Array, t: CandidateTable) -> Array:
    """Flank sliding speed [m/s]: n / 60 times the helix of one turn at d2."""
    return np.asarray(pv.surface_speed(rpm, t.flank_helix_travel_m), dtype=np.float64)


def _by_material_table(t: CandidateTable) -> dict[tuple[tuple[float, float], ...], list[int]]:
    """The candidates of ``t`` that have a pressure-speed table, grouped by table."""
    groups: dict[tuple[tuple[float, float], ...], list[int]] = {}
    for i, s in enumerate(t.screws):
        if s.bearing_pressure_table:
            groups.setdefault(s.bearing_pressure_table, []).append(i)
    return groups


def _table_pressures(t: CandidateTable, speed_m_s: Array) -> Array:
    """Each candidate's table pressure at its sliding speed [Pa] (NaN without a table);
    candidates sharing a material table are interpolated together."""
    out = np.full(len(t), np.nan)
    for table, index in per_table(t, "material tables", _by_material_table).items():
        out[index] = bearing.table_pressure(speed_m_s[index], table)
    return out


def allowed_pressure(t: CandidateTable, speed_m_s: Array) -> Array:
    """The nut material's allowable contact pressure at the sliding speed [Pa]."""
    allowed = bearing.allowable_pressure(
        _table_pressures(t, speed_m_s), t.max_pressure_pa, t.nut_pv_limit_pa_m_s, speed_m_s
    )
    return np.asarray(allowed, dtype=np.float64)


def _one(s: ScrewSpec, rpm: float) -> tuple[float, float]:
    """(sliding speed [m/s], allowed load [N]) of one candidate at ``rpm``."""
    t = table_of(s)
    speed = sliding_speed(np.array([rpm]), t)
    load = allowed_pressure(t, speed) * t.bearing_area_m2
    return float(speed[0]), float(load[0])


class BearingPressure(Check):
    name = "bearing_pressure"
    label = "Nut contact pressure"
    description = (
        "The load spread over the engaged flanks of the nut (nut length over pitch turns of "
        "pi d2 H1 each) against the contact pressure the nut material allows at the "
        "sliding speed: a bronze nut by its pressure-speed table, a polymer nut by its "
        "maximum pressure and its PV limit."
    )
    quantity = "force"
    formula = "F = F_axial; F_allow = p_nut_v * L_nut / P * pi * d_2 * H_1"
    source = (
        "Shigley, power-screw bearing stress over the engaged turns; Shigley Table 8-4 "
        "(after Rothbart) for bronze; the nut material's p_max and PV (catalog)"
    )
    sources = ("bearing_pressure", "max_pressure", "bearing_pv_limit", "nut_length", "pitch")
    capacity_sources = ("bearing_pressure", "max_pressure", "bearing_pv_limit", "nut_length")

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        speed = sliding_speed(q.rpm, t)
        capacity = allowed_pressure(t, speed) * t.bearing_area_m2
        return Measure(where_given(capacity), q.force_n, capacity)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_axial": q.force_n,
            "p_nut_v": allowed_pressure(t, sliding_speed(q.rpm, t)),
            "L_nut": t.nut_length_m,
            "P": t.pitch_m,
            "d_2": t.flank_pitch_diameter_m,
            "H_1": t.flank_height_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        speed, allowed = _one(s, r.rpm)
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "{f} " + verb + " the load {cap} that the nut's engaged flanks carry at the "
            "sliding speed {v}.",
            {
                "f": Amount(r.force_n, "force"),
                "cap": Amount(allowed, "force"),
                "v": Amount(speed, "speed"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase(
            "At this speed the load may be at most {cap}; a longer nut, a larger size or a "
            "nut material that allows more pressure carries more.",
            {"cap": Amount(_one(s, r.rpm)[1], "force")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {"load_n": load_input(app, _one(s, r.rpm)[1])}

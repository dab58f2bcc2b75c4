"""Ambient temperature within the assembly's operating range."""

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
)
from app.core.formulas import limits
from app.core.phrase import Amount, Phrase


class Temperature(Check):
    name = "temperature"
    why_none = (
        "no nut in the catalog is rated for this temperature: consider a metal nut outside "
        "the catalog or a ball screw"
    )
    why_none_ball = (
        "no ball screw in the catalog is rated for this temperature: consider one its maker "
        "rates for it outside the catalog"
    )
    label = "Operating temperature"
    description = "The ambient temperature against the assembly's rated range."
    formula = "passes when T_min <= T_ambient <= T_max"
    source = "catalog temperature range (see its provenance)"
    sources = ("temperature_range",)
    capacity_sources = ("temperature_range",)

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        t_min, t_max = t.temperature_min_c, t.temperature_max_c
        inside = limits.temperature_ok(app.ambient_c, t_min, t_max)
        given = t.temperature_given
        return Measure(given, flagged=given & ~inside)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "T_min": t.temperature_min_c,
            "T_max": t.temperature_max_c,
            "T_ambient": np.float64(app.ambient_c),
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "is outside"
        return Phrase(
            "{t} " + verb + " {low} to {high}.",
            {
                "t": Amount(app.ambient_c, "temperature"),
                "low": Amount(s.temperature_min_c or 0.0, "temperature"),
                "high": Amount(s.temperature_max_c or 0.0, "temperature"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase("Choose a screw rated for this temperature, or control the ambient.")

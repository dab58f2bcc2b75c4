"""An anti-backlash nut when the user asks for one."""

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
)
from app.core.phrase import Amount, Phrase


class AntiBacklash(Check):
    name = "anti_backlash"
    why_none = "no anti-backlash nut suits this axis: a preloaded ball screw"
    label = "Anti-backlash"
    description = "An anti-backlash (preloaded) nut when the axis must not have backlash."
    formula = "passes when anti_backlash"
    source = "catalog nut type"
    sources = ("type",)
    capacity_sources = ("type",)

    def applies(self, app: Application) -> bool:
        return app.require_anti_backlash

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), flagged=~t.anti_backlash)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"anti_backlash": t.anti_backlash}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        if passed:
            return Phrase("Anti-backlash nut.")
        if s.backlash_max_m is None:
            return Phrase("Free-wheeling nut; its axial play is not given.")
        return Phrase(
            "Free-wheeling nut with up to {backlash} backlash.",
            {"backlash": Amount(s.backlash_max_m, "length")},
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase("Choose an anti-backlash series.")

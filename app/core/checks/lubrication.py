"""A nut rated as a lubricated nut (a bronze nut) against an axis that runs it dry."""

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
from app.core.phrase import Amount, Phrase


class Lubrication(Check):
    name = "lubrication"
    kind = "advice"
    why_none = "every nut here is rated lubricated: grease or oil the nut"
    label = "Lubrication (bronze nut)"
    description = (
        "A bronze nut's flank pressures and wear rate are a lubricated nut's (steel on "
        "bronze with oil or grease). Where the axis runs the nut dry (the nut lubrication "
        "input), its numbers (torque, efficiency, heat, the start) are worked at its dry "
        "friction, steel on bronze dry 0.15 to 0.23 (0.19 taken; its range reaches down to "
        "the oiled 0.10), its holding at no more than its oiled static friction, as the nut "
        "may be oiled later, but its pressure and "
        "wear limits stay a lubricated nut's, with no dry basis: it is flagged, grease or "
        "oil it."
    )
    formula = "passes when not (lubricated_rating and dry)"
    source = (
        "Shigley's Mechanical Engineering Design, Table 8-5 (after Rothbart): steel on "
        "bronze, dry 0.15-0.23, machine oil 0.10-0.16; Table 8-4 (bearing pressures of "
        "lubricated screws)"
    )
    sources = ("lubricated_rating", "dry_friction_dynamic", "dry_friction_static")
    capacity_sources = ("lubricated_rating",)

    def applies(self, app: Application) -> bool:
        """The nut runs dry: none given, or oil or grease in a vacuum, where they
        evaporate (``Application.lubrication_counted``)."""
        return app.lubrication_counted == "dry"

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(t.lubricated_rating.copy(), flagged=t.lubricated_rating.copy())

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"lubricated_rating": t.lubricated_rating, "dry": self.applies(app)}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        head = (
            "In a vacuum oil and grease evaporate, so the nut runs dry"
            if app.lubricated
            else "The nut is to run dry"
        )
        return Phrase(
            head + ": its numbers here are at its dry friction, running "
            "{mu_d} and static {mu_s} (steel on bronze dry rubs at 0.15 to 0.23, oiled 0.10 "
            "to 0.16), its holding at no more than its oiled static friction (it may be "
            "oiled later), but its pressure and wear ratings are still a lubricated nut's.",
            {
                "mu_d": Amount(s.friction_dynamic, "factor"),
                "mu_s": Amount(s.friction_static, "factor"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        return Phrase("Grease or oil the nut (the nut lubrication input), or use a polymer nut.")

"""Compressive axial force against the allowed fraction of the Euler buckling load."""

from app.core.checks import register
from app.core.checks.base import (
    Application,
    Array,
    CandidateTable,
    Check,
    EndFixity,
    Mapping,
    Measure,
    Quantities,
    ScrewSpec,
    everywhere,
    load_input,
    stiffer_support,
)
from app.core.formulas import buckling
from app.core.phrase import Amount, Phrase


@register
class ColumnBuckling(Check):
    name = "buckling"
    label = "Column buckling"
    description = (
        "A screw pushed in compression buckles as a column; the allowed force is a fraction "
        "(the buckling factor) of the Euler load at the root diameter."
    )
    quantity = "force"
    formula = "F = F_axial; F_allowed = SF * k * pi^2 * E * (pi * d_r^4 / 64) / L^2"
    source = "Euler column; Timoshenko & Gere, Theory of Elastic Stability"
    sources = ("root_diameter", "youngs_modulus")
    order = 30

    def applies(self, app: Application) -> bool:
        return app.compression

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(everywhere(t), q.force_n, q.allowed_load_n)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {
            "F_axial": q.force_n,
            "SF": app.buckling_safety_factor,
            "k": buckling.END_FIXITY_K[app.end_fixity],
            "E": t.youngs_modulus_pa,
            "d_r": t.root_diameter_m,
            "L": app.length_m,
        }

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        return Phrase(
            "{f} compression " + verb + " the allowed {allowed} ({sf} x Euler {f_cr}).",
            {
                "f": Amount(r.force_n, "force"),
                "allowed": Amount(r.allowed_load_n, "force"),
                "sf": Amount(app.buckling_safety_factor, "factor"),
                "f_cr": Amount(r.critical_load_n, "force"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float]) -> Phrase:
        def passes(fixity: EndFixity) -> bool:
            f_cr = buckling.euler_critical_load(
                s.youngs_modulus_pa,
                buckling.second_moment_round(s.root_diameter_m),
                app.length_m,
                fixity,
            )
            return r.force_n <= app.buckling_safety_factor * f_cr

        return Phrase(
            "Use a root diameter of at least {d}, or {support} (column at most {length}), "
            "or load the screw in tension.",
            {
                "d": Amount(
                    buckling.min_root_diameter_for_load(
                        s.root_diameter_m, r.allowed_load_n, r.force_n
                    ),
                    "length",
                ),
                "support": stiffer_support(app, passes),
                "length": Amount(
                    buckling.max_length_for_load(app.length_m, r.allowed_load_n, r.force_n),
                    "length",
                ),
            },
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {
            "load_n": load_input(app, r.allowed_load_n),
            "length_m": buckling.max_length_for_load(app.length_m, r.allowed_load_n, r.force_n),
        }

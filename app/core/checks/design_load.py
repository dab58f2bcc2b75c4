"""Axial force against the load the nut is rated for in motion: the size's design load
(when the catalog gives one), else the nut's allowable dynamic thrust (its flank pressure
in motion, taken from its maker's thrust table, over the engaged flank area)."""

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
    load_input,
    most,
    where_given,
)
from app.core.phrase import Amount, Phrase


class DesignLoad(Check):
    name = "design_load"
    why_none = "the thrust exceeds every screw's design load: consider a ball screw"
    label = "Design load"
    description = (
        "The peak thrust (running load plus the force that accelerates or brakes the "
        "moving mass, the larger) against the load the nut of this size is designed for: "
        "the size's design load, or for a sliding nut its allowable dynamic thrust: the "
        "maker's published thrust for the size (or, for a size its table does not list, "
        "the lowest flank pressure of the listed sizes) as a flank pressure in motion over "
        "the engaged flanks (nut length over pitch turns of pi d2 H1 each), a nut "
        "longer than the catalog's held to the catalog nut's thrust."
    )
    quantity = "force"
    formula = "F = F_peak; F_design = F_size"
    source = (
        "catalog design load of the size, or p_dyn x (min(L_nut, L_catalog) / P) pi d2 H1, "
        "p_dyn from the nut maker's allowable dynamic thrust table (see its provenance)"
    )
    sources = ("design_load", "dynamic_pressure", "nut_length", "pitch")
    capacity_sources = ("design_load", "dynamic_pressure", "nut_length")

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        return Measure(where_given(q.nut.rated_load_n), q.axis.peak_force_n, q.nut.rated_load_n)

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"F_peak": q.axis.peak_force_n, "F_size": q.nut.rated_load_n}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "is within" if passed else "exceeds"
        values: dict[str, Amount | str] = {
            "f": Amount(r.axis.peak_force_n, "force"),
            "cap": Amount(r.nut.rated_load_n, "force"),
        }
        if s.design_load_n is not None or s.dynamic_pressure_pa is None:
            return Phrase("Peak thrust {f} " + verb + " the design load {cap}.", values)
        values.update(_polymer_values(s))
        held = ""
        if _longer_than_rated(app, s):
            held = (
                " The {length} nut is held to the rating of the {rated} nut the maker's "
                "thrust is read over: a maker rates the nut it sells, and a longer nut's "
                "turns do not share the thrust evenly."
            )
            values["length"] = Amount(app.nut_length_m or 0.0, "length")
            values["rated"] = Amount(s.nut_length_m or 0.0, "length")
        return Phrase(
            "Peak thrust {f} " + verb + " the allowable dynamic thrust {cap} of this "
            "{material} nut: {p} over its engaged flanks ({kind}: {source})." + held,
            values,
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        if s.design_load_n is None:
            # a nut at or above the rated nut's length carries no more (``nut.rating``)
            shorter = app.nut_length_m is not None and app.nut_length_m < (s.nut_length_m or 0.0)
            longer = "a longer nut, " if shorter else ""
            return Phrase(
                "Reduce the peak thrust to at most {cap}, or carry it on " + longer + "a "
                "larger size or a nut material rated higher in motion." + MARGIN_NOTE,
                {"cap": most(r.nut.rated_load_n, "force")},
            )
        larger = (
            " or choose a larger size" if reach.max_design_load_n >= r.axis.peak_force_n else ""
        )
        return Phrase(
            "Reduce the peak thrust to at most {cap}" + larger + "." + MARGIN_NOTE,
            {"cap": most(r.nut.rated_load_n, "force")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return load_input(app, r.nut.rated_load_n)


def _longer_than_rated(app: Application, s: ScrewSpec) -> bool:
    """Whether the axis's nut is longer than the one its maker's thrust is read over."""
    rated = s.nut_length_m
    return app.nut_length_m is not None and rated is not None and app.nut_length_m > rated


def _polymer_values(s: ScrewSpec) -> dict[str, Amount | str]:
    """The nut's rating in motion in words: material, pressure and where it comes from."""
    prov = s.provenance.get("dynamic_pressure")
    return {
        "material": s.nut_material or "sliding",
        "p": Amount(s.dynamic_pressure_pa or 0.0, "pressure"),
        "kind": prov.kind if prov else "derived",
        "source": prov.source if prov else "catalog",
    }

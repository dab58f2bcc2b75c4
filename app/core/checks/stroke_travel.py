"""The stroke and the nut on the screw: the nut travels the stroke between the screw's ends.

The input refuses a stroke of the screw's length or more (less the nut length when one is
typed); the catalog nut's own length differs by size (a trapezoidal nut twice the
diameter), so that each candidate's is judged here.
"""

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
    at_most,
    least,
    same,
    where_given,
)
from app.core.phrase import Amount, Phrase


class StrokeTravel(Check):
    name = "stroke_travel"
    label = "Stroke on the screw"
    description = (
        "The nut travels the stroke between the screw's ends: the stroke plus the nut's "
        "length (the one typed, else the catalog's) must fit in the screw length. Where the "
        "catalog gives no nut length the input's own limit (stroke under the screw length) "
        "is all that is judged."
    )
    quantity = "length"
    formula = "s_total = stroke + L_nut; L = L_screw"
    source = "geometry: the nut stays on the thread over the whole stroke"
    sources = ("nut_length",)

    def applies(self, app: Application) -> bool:
        return app.stroke_m is not None

    def measure(self, app: Application, t: CandidateTable, q: Quantities[Array]) -> Measure:
        nut_m = _whole_nuts(app, t)
        total = (app.stroke_m or 0.0) + nut_m
        return Measure(where_given(nut_m), total, same(t, app.length_m))

    def symbols(
        self, app: Application, t: CandidateTable, q: Quantities[Array]
    ) -> Mapping[str, object]:
        return {"stroke": app.stroke_m, "L_nut": _whole_nuts(app, t), "L_screw": app.length_m}

    def explain(self, app: Application, s: ScrewSpec, r: Quantities[float], passed: bool) -> Phrase:
        verb = "fit within" if passed else "exceed"
        return Phrase(
            "The stroke {s} and the nut {nut} " + verb + " the screw length {L}.",
            {
                "s": Amount(app.stroke_m or 0.0, "length"),
                "nut": Amount(_whole_nut(app, s), "length"),
                "L": Amount(app.length_m, "length"),
            },
        )

    def fix(self, app: Application, s: ScrewSpec, r: Quantities[float], reach: Reach) -> Phrase:
        nut_m = _whole_nut(app, s)
        longer = {"L": least((app.stroke_m or 0.0) + nut_m, "length")}
        # the stroke plus the nut kept FIX_MARGIN inside the screw length, as promised
        room = at_most(app.length_m) - nut_m
        if room <= 0.0:
            return Phrase("Lengthen the screw to at least {L}." + MARGIN_NOTE, longer)
        return Phrase(
            "Shorten the stroke to at most {s}, or lengthen the screw to at least {L}."
            + MARGIN_NOTE,
            {**longer, "s": Amount(room, "length", "down")},
        )

    def input_limits(
        self, app: Application, s: ScrewSpec, r: Quantities[float]
    ) -> Mapping[str, float]:
        return {"length_m": (app.stroke_m or 0.0) + _whole_nut(app, s)}


def _whole_nuts(app: Application, t: CandidateTable) -> Array:
    """Each candidate's nut length [m]: the one typed, else the catalog's (NaN: none), the
    whole nut, whether or not its turns' share of the load is rated (a ball nut's)."""
    return t.nut_length_m if app.nut_length_m is None else same(t, app.nut_length_m)


def _whole_nut(app: Application, s: ScrewSpec) -> float:
    """``_whole_nuts`` of one screw [m] (NaN: none)."""
    length = app.nut_length_m if app.nut_length_m is not None else s.nut_length_m
    return float("nan") if length is None else length

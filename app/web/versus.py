"""The leadscrew-against-ball-screw view: the compare rows of the two kinds' best
screws (``app.web.compare``) and the rows that only matter between kinds, each value
read from the candidates' output models (the API's numbers), shown in the display units.
"""

from collections.abc import Sequence

from app.contract.schemas import CandidateOut
from app.contract.sections import LifeOut
from app.contract.units import Display
from app.core.phrase import figures
from app.web.compare import Row, best_columns, compare_rows


def _holds(c: CandidateOut) -> str:
    """Whether the load stays put with the power off, and by what; when the axis does not
    ask for it (``holds_power_off`` None), what the thread alone does, as the results
    table's holding cell says it."""
    if c.holds_power_off is None:
        if c.self_locking_with_margin:
            return "yes: the thread self-locks"
        return "nothing to hold" if c.holding_torque.brake_nm == 0.0 else "no: a brake is needed"
    if not c.holds_power_off:
        return "no: a brake is needed"
    if c.holds_by == "thread":
        return "yes: the thread self-locks"
    return f"yes: by the {c.holds_by}" if c.holds_by else "yes"


def _life(c: CandidateOut, d: Display) -> str:
    """The life in years of the duty: a leadscrew's wear band, a ball nut's L10 (its
    check's capacity, given a required life); the travel when no duty gives years."""
    l10 = next((k.limit for k in c.checks if k.name == "ball_life"), None)
    if l10 is not None:
        return f"{figures(l10)} years (L10)"
    if c.life is None:
        return "—"
    if c.life.years:
        return f"{_band(c.life.years)} years ({_basis(c.life)})"
    travel = _band([d.value(v, "travel") for v in c.life.travel_km])
    return f"{travel} {d.label('travel')} travelled ({_basis(c.life)})"


def _band(ends: list[float]) -> str:
    """A band's ends as the results table writes them: one figure when they are equal
    (a ball nut's L10)."""
    return "–".join(dict.fromkeys(figures(v) for v in ends))


def _basis(life: LifeOut) -> str:
    """The life's model, and where the nut's wear cuts the seed's rating, that."""
    if life.model == "l10":
        return "L10"
    return "rated, cut by wear" if life.capped_by_wear else life.model


def _low(band: list[float] | None) -> float | None:
    return band[0] if band else None


def kind_rows(cs: Sequence[CandidateOut], d: Display) -> list[Row]:
    """The rows that differ in kind between a leadscrew and a ball screw: holding with
    the power off, the lead error and the nut's play (backlash)."""
    holds = tuple(_holds(c) for c in cs)
    errors = [c.accuracy.lead_error_mm for c in cs]
    plays = [c.accuracy.backlash_mm for c in cs]
    length = d.label("length")
    return [
        Row("holds_power_off", "Holds with the power off", "", holds, frozenset(), None),
        Row("life", "Life (wear or L10)", "", tuple(_life(c, d) for c in cs), frozenset(), None),
        Row(
            "accuracy.lead_error_mm",
            "Lead error over the stroke",
            length,
            tuple("—" if e is None else d.text(e, "length", 3) for e in errors),
            best_columns(errors, "lower"),
            "lower",
        ),
        Row(
            "accuracy.backlash_mm",
            "Backlash (axial play)",
            length,
            tuple("—" if not p else "–".join(d.text(v, "length", 3) for v in p) for p in plays),
            best_columns([_low(p) for p in plays], "lower"),
            "lower",
        ),
    ]


def versus_rows(cs: Sequence[CandidateOut], d: Display) -> list[Row]:
    """Every row of the view: the compare rows, then the rows between kinds."""
    return [*compare_rows(cs, d), *kind_rows(cs, d)]

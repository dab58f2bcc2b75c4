"""The inputs' own rules, which hold between inputs whatever the screw: the screw at least
as long as the stroke, the nut and the span to the thrust bearing given, that span at least
the nut's travel, and the cycles a day within a day. The input model refuses an
application that breaks one (``ApplicationInputs``); a change the app offers keeps them
(``changes``, ``remedy``), and a check's fix says where the move it names breaks one
(``refused``)."""

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Any, cast

from app.core import duty, motion
from app.core.checks.base import at_least, at_most
from app.core.formulas import life
from app.core.model import Application
from app.core.phrase import Amount, Phrase

#: The inputs a check's fix may name that set how long a cycle takes, each with the
#: words for a value of it that makes the cycle too long.
MOVE_INPUTS = {
    "speed_m_s": "a move that slow",
    "accel_m_s2": "a move that slow",
    "dwell_s": "a dwell that long",
}
#: The scalar inputs of the move that a cycle of the user's own moves replaces (each of
#: its moves gives its own): a change of one moves nothing there.
REPLACED_BY_MOVES = frozenset(
    {"speed_m_s", "accel_m_s2", "decel_m_s2", "dwell_s", "moving_mass_kg", "load_n"}
)


def read_inputs(app: Application, limits: Mapping[str, float] | None) -> dict[str, float]:
    """The inputs of a check's ``input_limits`` that ``app`` reads: all of them, but in a
    cycle of the user's own moves none the moves replace (``REPLACED_BY_MOVES``)."""
    return {
        key: value
        for key, value in (limits or {}).items()
        if not (app.moves and key in REPLACED_BY_MOVES)
    }


def travel_span_m(app: Application) -> float | None:
    """The length of screw the nut's travel spans [m]: the stroke, else the span of the
    positions a cycle of moves reaches from its start (``motion.position_span``); None
    without either."""
    if app.stroke_m is not None or not app.moves:
        return app.stroke_m
    return motion.position_span(m.distance_m for m in app.moves)


def least_inputs(app: Application) -> dict[str, float]:
    """The least value of each input that the other inputs' rules set: the screw's
    length, at least the stroke and the nut length given (the input table's rule,
    ``ApplicationInputs._stroke_fits``), the nut length alone and the span from the thrust
    bearing to the nut given (``ApplicationInputs._within_length``); and that span, given,
    at least the nut's travel (``travel_span_m``: the nut at the far end of its travel is
    that far from the bearing at least, ``ApplicationInputs._span_holds_the_travel``);
    ``inputs_hold``."""
    least = [app.stroke_m + (app.nut_length_m or 0.0)] if app.stroke_m is not None else []
    least += [v for v in (app.nut_length_m, app.bearing_to_nut_m) if v is not None]
    out = {"length_m": max(least)} if least else {}
    travel = travel_span_m(app)
    if app.bearing_to_nut_m is not None and travel:
        out["bearing_to_nut_m"] = travel
    return out


def inputs_hold(app: Application) -> bool:
    """The inputs' own rules hold: the screw is at least as long as the stroke and the
    nut length given and the span from the thrust bearing to the nut (the rules
    ``least_inputs`` gives and every ``input_change`` keeps), and the cycles per day fit
    in a day (``ApplicationInputs._cycles_fit_a_day``, ``duty.cycles_fit_a_day``). A
    change that breaks one (a screw shortened below a seed nut's stroke, which no
    stroke-travel check judges without the nut's length; a move slowed until 5,000
    cycles take more than a day) is no application the inputs accept."""
    if any(getattr(app, key) < least for key, least in least_inputs(app).items()):
        return False
    return app.cycles_per_day is None or duty.cycles_fit_a_day(
        app.cycles_per_day, motion.move_profile(app)
    )


def lowers(app: Application, key: str, limit: float) -> bool:
    """Whether an input's offered ``limit`` lowers it from its value in ``app`` (a most)
    rather than raising it (a least); an input not given is set to it."""
    value = getattr(app, key, None)
    return not isinstance(value, int | float) or limit <= value


def refused(app: Application, limits: Mapping[str, float] | None) -> Phrase | None:
    """Why the inputs refuse a move the values of a check's fix name (its
    ``input_limits``, each ``FIX_MARGIN`` inside its limit, as the fix writes it): a
    speed or an acceleration so low, or a dwell so long, that the cycles a day no longer
    fit in a day; None where none does. The fix names what the screw needs; this says
    that the application cannot give it that way (the load, or another input the fix
    names, may still do). A length a fix names needs no such word: the checks that name
    one say how to keep the stroke (an intermediate support, a shorter span to the thrust
    bearing)."""
    if app.cycles_per_day is None:
        return None  # no cycles a day to fit
    for key, limit in (limits or {}).items():
        if key not in MOVE_INPUTS or not math.isfinite(limit) or limit <= 0.0:
            continue
        value = at_most(limit) if lowers(app, key, limit) else at_least(limit)
        p = motion.move_profile(replace(app, **cast(dict[str, Any], {key: value})))
        if p is not None and not duty.cycles_fit_a_day(app.cycles_per_day, p):
            return Phrase(
                f"The inputs refuse {MOVE_INPUTS[key]}: a cycle would take {{cycle}}, and "
                "{cycles} cycles a day leave {each} for each.",
                {
                    "cycle": Amount(p.cycle_time_s, "time"),
                    "cycles": f"{app.cycles_per_day:,.0f}",
                    "each": Amount(life.SECONDS_PER_DAY / app.cycles_per_day, "time"),
                },
            )
    return None
